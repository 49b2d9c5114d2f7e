#pragma once
// The protective separation check: the half of speed and separation monitoring (ISO/TS 15066)
// that the look-ahead cannot give. The look-ahead keeps the robot out of the cells the map
// forbids along its way; a person who walks into the side of a moving robot is in no cell ahead
// of it, and the robot's own cell turns forbidden only when they all but touch it - the robot is
// then still braking when they meet (controller/SAFETY_CASE.md, "Direction").
//
// The check, once per map cycle at the robot's configuration at the exposure: each robot part
// (robot_parts.hpp), its balls grown by the separation distance S and the removal's widening, is
// projected into every camera. When, for some part, at least `camera_threshold` cameras see an
// obstacle (after robot removal) inside that grown image, or have an unknown view, a person may
// be within S of the part and the robot must stop: the service then forbids the whole map.
//
// Why it is conservative: a point within S of a part lies inside the part's grown balls, so in
// every camera that sees the point its pixel lies inside the grown part's image - the argument of
// the tables' envelope, for one configuration and a larger margin. S covers the person's approach
// from the exposure until the robot is at rest (cell_config.hpp, SeparationDistanceConfig).
//
// Thread context: the pipeline's; not thread-safe (scratch masks are members).

#include <cstddef>
#include <span>
#include <string>
#include <vector>

#include "safecell/cell/cell_model.hpp"
#include "safecell/features/feature_mask.hpp"
#include "safecell/fusion/camera_observation.hpp"
#include "safecell/robot/robot_parts.hpp"
#include "safecell/silhouettes/configuration_silhouettes.hpp"

namespace safecell {

struct SeparationVerdict {
  bool too_close = false;            // some part has an obstacle within S in enough cameras
  std::size_t part = 0;              // the first such part, when too_close
  std::vector<std::size_t> cameras;  // the cameras that voted for it (unknown views among them)
};

class ProtectiveSeparation {
 public:
  // widening_m: the removal's (padding and the motion within the sync error); separation_m: S.
  // Throws std::invalid_argument for no parts, a threshold outside 1..cameras, S outside
  // 0..0.95 m, or what ConfigurationSilhouettes refuses.
  ProtectiveSeparation(const CellModel& cell, std::vector<RobotPart> parts, double ball_radius_m,
                       double widening_m, double separation_m, int camera_threshold);

  [[nodiscard]] double separation_m() const { return separation_m_; }
  [[nodiscard]] const std::vector<RobotPart>& parts() const { return parts_; }

  // The vote at joint values q (rad): `known[c]` whether camera c's view was known,
  // `obstacles[c]` its obstacles after robot removal (not read for an unknown view). Throws
  // std::invalid_argument for counts that are not the cameras'.
  [[nodiscard]] SeparationVerdict check(std::span<const double> q, const std::vector<bool>& known,
                                        const std::vector<const FeatureMask*>& obstacles) const;
  // The grown image of part `part` at q in every camera (for pictures and tests).
  [[nodiscard]] std::vector<FeatureMask> grown_part(std::span<const double> q,
                                                    std::size_t part) const;

 private:
  std::vector<RobotPart> parts_;
  double separation_m_;
  int camera_threshold_;
  FeatureGrid grid_;
  ConfigurationSilhouettes grown_;
  mutable std::vector<FeatureMask> scratch_;
};

// "an obstacle within the protective separation distance: 0.64 m of the robot's upper arm
// (links 1-2) in cameras 'cam0', 'cam2'": the reason of a map forbidden whole (its kind is the
// text before the colon).
std::string describe(const SeparationVerdict& verdict, const ProtectiveSeparation& check,
                     const CellModel& cell);

}  // namespace safecell
