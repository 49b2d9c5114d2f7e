#pragma once
// The protective separation check (separation/protective_separation.hpp) of one scene against
// the exact ground truth: FCL distances between the robot at the scene's configuration and each
// human and object, and the renderer's object-id images for what each camera sees
// (body_visibility.hpp), never the pipeline's output.
//   within    some body visible in at least `camera_threshold` cameras is nearer the robot than
//             S (the check's distance);
//   missed    of those, scenes where the check did not stop the robot. Must be 0;
//   far       every body is at least S + kClearDistance_m from the robot;
//   needless  of those, scenes where the check stopped the robot all the same (its price: the
//             grown silhouettes' visual hull, as for the map's needless stops).

#include <cstddef>
#include <vector>

#include <opencv2/core.hpp>

#include "safecell/cell/cell_model.hpp"
#include "safecell/sim/simulated_cell.hpp"

namespace safecell {

struct SeparationFigures {
  std::size_t scenes = 0;  // scenes the check ran on
  std::size_t fired = 0;   // of them, scenes it stopped the robot in
  std::size_t within = 0;
  std::size_t missed = 0;
  std::size_t far = 0;
  std::size_t needless = 0;

  SeparationFigures& operator+=(const SeparationFigures& other);
  friend bool operator==(const SeparationFigures&, const SeparationFigures&) = default;
  // Stopped among the far scenes.
  [[nodiscard]] double needless_share() const;
};

// world: the simulated cell as it really is (its robot model for FCL); object_ids: per camera,
// from rendering the scene; fired: the check's verdict on the scene's frames.
[[nodiscard]] SeparationFigures check_separation(const CellModel& world, const SimScene& scene,
                                                 const std::vector<cv::Mat>& object_ids,
                                                 int camera_threshold, double separation_m,
                                                 bool fired);

}  // namespace safecell
