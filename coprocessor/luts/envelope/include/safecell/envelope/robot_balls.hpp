#pragma once
// The robot's collision geometry covered by balls, per body (the base and each link): every
// point of every shape's surface lies inside a ball of its body. Balls make the conservative
// envelope of a C-space cell cheap (cell_envelope.hpp): a ball stays a ball under the sweep of a
// joint, only larger, and its image in a camera has a closed-form bounding box.
//
// Only surfaces are covered. That suffices for silhouettes (a closed surface's image is the
// solid's image) and for obstacles that are larger than the gaps between balls; a static box
// wholly inside a link would be missed, which a cell never has.

#include <Eigen/Core>
#include <vector>

#include "safecell/robot/robot_model.hpp"

namespace safecell {

struct Ball {
  Eigen::Vector3d centre_m = Eigen::Vector3d::Zero();
  double radius_m = 0.0;
};

struct RobotBalls {
  std::vector<Ball> base;                // in the base frame
  std::vector<std::vector<Ball>> links;  // links[j] in link j's frame (moved by joints 0..j)

  [[nodiscard]] std::size_t count() const;
};

// Covers every collision shape of `model` with balls of about `target_radius_m` (the surface is
// sampled to within a quarter of it). Throws std::invalid_argument for a target radius that is not
// finite and > 0, and for a shape whose tessellation is empty or not finite.
[[nodiscard]] RobotBalls cover_with_balls(const RobotModel& model, double target_radius_m);

// Balls over the given shapes (in their parent frame), as cover_with_balls() does for one body.
[[nodiscard]] std::vector<Ball> cover_shapes_with_balls(const std::vector<PlacedShape>& shapes,
                                                        double target_radius_m);

}  // namespace safecell
