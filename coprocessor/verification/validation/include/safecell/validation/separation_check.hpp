#pragma once
// The protective separation check (separation/protective_separation.hpp) of one scene against
// the exact ground truth: FCL distances between the robot at the scene's configuration and each
// human and object, and the renderer's object-id images for what each camera sees
// (body_visibility.hpp), never the pipeline's output.
//   within    some body visible in at least `camera_threshold` cameras is nearer the robot than
//             S at full speed;
//   missed    of all scenes, those where such a body was nearer than the distance the check
//             found clear (S of the speed it allowed; a stop allows none). Must be 0;
//   slowed, stopped   scenes the check slowed the robot in (a reduced speed) or stopped it in;
//   far       every body is at least S + kClearDistance_m from the robot;
//   needless  of those, scenes where the check slowed or stopped the robot all the same (its
//             price: the grown silhouettes' visual hull, as for the map's needless stops).

#include <cstddef>
#include <vector>

#include <opencv2/core.hpp>

#include "safecell/cell/cell_model.hpp"
#include "safecell/sim/simulated_cell.hpp"

namespace safecell {

struct SeparationFigures {
  std::size_t scenes = 0;  // scenes the check ran on
  std::size_t fired = 0;   // of them, scenes it slowed or stopped the robot in
  std::size_t slowed = 0;  // of those, slowed (not stopped)
  std::size_t within = 0;
  std::size_t missed = 0;
  std::size_t far = 0;
  std::size_t needless = 0;

  SeparationFigures& operator+=(const SeparationFigures& other);
  friend bool operator==(const SeparationFigures&, const SeparationFigures&) = default;
  // Slowed or stopped among the far scenes.
  [[nodiscard]] double needless_share() const;
};

// world: the simulated cell as it really is (its robot model for FCL); object_ids: per camera,
// from rendering the scene; separation_m: S at full speed; the check's verdict on the scene's
// frames: the speed it allowed (1 none taken off, 0 a stop) and the distance it found clear.
[[nodiscard]] SeparationFigures check_separation(const CellModel& world, const SimScene& scene,
                                                 const std::vector<cv::Mat>& object_ids,
                                                 int camera_threshold, double separation_m,
                                                 double speed_limit, double clear_m);

}  // namespace safecell
