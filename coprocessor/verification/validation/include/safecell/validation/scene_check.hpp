#pragma once
// Checks one processed scene of the simulated cell against the exact ground truth
// (../shared/VALIDATION.md). Robot configurations of the three configuration strata
// (configuration_strata.hpp) are tested for collision with FCL, against every body they touch,
// and compared with the forbidden map the pipeline made:
//   missed    the configuration touches a static obstacle, or a human or object visible
//             (body_visibility.hpp, from the renderer's object-id images) in at least
//             `camera_threshold` cameras, and its cell is not forbidden. Must be 0.
//   unseen    it collides, but every body it touches is visible in fewer cameras; counted with
//             the reason of the first such body (the reason most of the cameras that miss it
//             give), and whether the cell is forbidden all the same.
//   clear     its robot stays at least `clear_distance_m` from every body (static ones too);
//             forbidden clear configurations are needless stops. Up to `decompose` of them per
//             scene are traced to a cause, the first that holds:
//               in_cell      the cell also holds a colliding configuration (dense sampling: the
//                            price of the cell's size);
//               visual_hull  at configurations sampled inside the cell, the exact silhouettes of
//                            one robot part (the parts the cameras vote on) still meet obstacle
//                            pixels in `camera_threshold` cameras (phantoms, the visual hull, what
//                            stands in front of or behind a body);
//               envelope     the rest: only the conservative envelope (LUT-1 with its padding and
//                            sweeps) meets them.
// Scene-level counts go to the scene's stratum and to the configuration's stratum both.
// Shared by `safecell validate` and `safecell demo`.

#include <cstddef>
#include <map>
#include <opencv2/core/mat.hpp>
#include <random>
#include <string>
#include <vector>

#include "safecell/cell/cell_model.hpp"
#include "safecell/cellsets/cell_set.hpp"
#include "safecell/robot/robot_parts.hpp"
#include "safecell/sim/simulated_cell.hpp"
#include "safecell/validation/body_visibility.hpp"

namespace safecell {

struct MissedCollision {
  std::size_t scene = 0;
  std::string stratum;  // the scene's
  std::vector<double> q;
  std::string body;
  int cameras_visible = 0;
};

// The figures of one stratum, all additive.
struct StratumCounts {
  std::size_t configs = 0;
  std::size_t colliding = 0;
  std::size_t missed = 0;
  std::size_t unseen = 0;
  std::size_t clear = 0;
  std::size_t clear_forbidden = 0;

  StratumCounts& operator+=(const StratumCounts& other);
  friend bool operator==(const StratumCounts&, const StratumCounts&) = default;
  // Forbidden among the clear configurations.
  [[nodiscard]] double needless_stop_share() const;
};

// Needless stops traced to a cause (see above), all additive.
struct NeedlessStopCauses {
  std::size_t traced = 0;
  std::size_t in_cell = 0;
  std::size_t visual_hull = 0;
  std::size_t envelope = 0;

  NeedlessStopCauses& operator+=(const NeedlessStopCauses& other);
  // `part` (one of the causes) as a share of the traced needless stops.
  [[nodiscard]] double share(std::size_t part) const;
  friend bool operator==(const NeedlessStopCauses&, const NeedlessStopCauses&) = default;
};

struct SceneCheck {
  std::size_t configs_checked = 0;
  std::size_t colliding = 0;
  std::size_t missed = 0;
  std::size_t unseen = 0;
  std::size_t unseen_forbidden = 0;  // unseen, yet forbidden all the same
  UnseenReasons unseen_reasons{};
  std::size_t free = 0;             // not colliding
  std::size_t false_positives = 0;  // free but forbidden
  std::size_t clear = 0;
  std::size_t clear_forbidden = 0;
  NeedlessStopCauses causes;
  std::size_t bodies = 0;                 // humans and objects placed
  std::size_t bodies_visible_enough = 0;  // visible in at least camera_threshold cameras
  std::map<std::string, StratumCounts> strata;
  std::vector<MissedCollision> missed_cases;  // the first few

  SceneCheck& operator+=(const SceneCheck& other);
  // Forbidden but free, as a share of the free configurations checked.
  [[nodiscard]] double false_positive_rate() const;
  // Forbidden among the clear configurations.
  [[nodiscard]] double needless_stop_share() const;
};

// One scene and what the pipeline made of its frames.
struct SceneUnderTest {
  const SimScene& scene;
  const std::vector<cv::Mat>& object_ids;  // per camera, from rendering the scene's frames
  const CellSet& forbidden;                // the pipeline's forbidden map for those frames
  int camera_threshold = 2;
  std::string stratum;  // the scene's stratum, for the report
  std::size_t index = 0;
  // Per camera, the obstacle pixels fusion back-projected (after robot removal; empty for an
  // unknown view), and how many needless stops to trace to a cause: none without them.
  const std::vector<FeatureMask>* obstacles = nullptr;
  std::size_t decompose = 0;
  // The robot parts the cameras voted on (the tables'); null: the whole robot.
  const std::vector<RobotPart>* parts = nullptr;
};

inline constexpr double kClearDistance_m = 0.5;

[[nodiscard]] SceneCheck check_scene(const CellModel& cell, const CspaceGrid& grid,
                                     SimulatedCell& sim, const SceneUnderTest& under_test,
                                     std::size_t configurations, std::mt19937_64& rng);

// The shapes of the scene's humans and objects.
[[nodiscard]] std::vector<PlacedShape> moving_bodies(const SimScene& scene);

}  // namespace safecell
