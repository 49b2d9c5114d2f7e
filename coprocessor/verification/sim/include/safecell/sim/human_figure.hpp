#pragma once
// A simulated human: an articulated figure of a head sphere and nine capsules, about 1.75 m tall,
// posed in the cell frame (z up, floor at z = 0). Walking swings the legs and arms in the
// sagittal plane; the pelvis sinks as the legs spread so that the lower foot always stands on the
// floor. The swing is shaped for silhouettes and collisions, not for gait analysis: the feet
// slide a little.

#include <Eigen/Core>
#include <cstddef>
#include <vector>

#include "safecell/geometry/shape.hpp"

namespace safecell {

struct HumanPose {
  Eigen::Vector2d position_m = Eigen::Vector2d::Zero();  // pelvis, projected onto the floor
  double heading_rad = 0.0;     // facing direction, counter-clockwise from the cell's +x axis
  double gait_phase_rad = 0.0;  // one gait cycle (two steps) is 2 pi; 0: legs passing each other
  double arm_raise_rad = 0.0;   // both arms raised forward about the shoulders; 0: hanging
  double gait_amplitude = 1.0;  // scales the leg and arm swing: 0 standing still, 1 walking
  // Above 0: the right arm reaches out forward, elbow straight, raised this far from hanging
  // (pi / 2: level with the shoulder), and does not swing. 0: it hangs and swings as the left.
  double right_arm_reach_rad = 0.0;
};

// human_shapes() returns the parts in this order (left is the figure's own left).
enum class HumanPart : std::size_t {
  kTorso,
  kHead,
  kLeftUpperArm,
  kLeftForearm,  // with the hand
  kRightUpperArm,
  kRightForearm,
  kLeftThigh,
  kLeftShank,  // down to the sole
  kRightThigh,
  kRightShank,
};
inline constexpr std::size_t kHumanPartCount = 10;

// The figure's shapes in the cell frame, indexed by HumanPart.
std::vector<PlacedShape> human_shapes(const HumanPose& pose);

}  // namespace safecell
