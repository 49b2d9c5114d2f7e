#pragma once
// A simulated human walking a polyline of floor waypoints at constant speed, facing along the
// path and swinging legs and arms at a constant cadence; after the last waypoint the figure stands
// still there, facing along the last segment.

#include <Eigen/Core>
#include <vector>

#include "safecell/sim/human_figure.hpp"

namespace safecell {

// ISO 13855: the approach speed of a walking person, for separation distances.
inline constexpr double kWalkingSpeed_m_s = 1.6;
inline constexpr double kMaxWalkingSpeed_m_s = 3.0;
// Steps per second at any speed; one gait cycle (2 pi of gait phase) is two steps.
inline constexpr double kCadence_steps_s = 1.8;

class HumanWalker {
 public:
  // Throws std::invalid_argument naming the field and its value unless there is at least one
  // waypoint, every coordinate is finite, 0 < speed_m_s <= kMaxWalkingSpeed_m_s and
  // arm_raise_rad is finite. Repeated waypoints are allowed (a segment of length 0 is skipped).
  explicit HumanWalker(std::vector<Eigen::Vector2d> waypoints_m,
                       double speed_m_s = kWalkingSpeed_m_s, double arm_raise_rad = 0.0);

  // The pose time_s after leaving the first waypoint; times before 0 give the pose at 0.
  // Throws std::invalid_argument when time_s is NaN.
  HumanPose pose_at(double time_s) const;

  double path_length_m() const { return distance_at_m_.back(); }
  // When the last waypoint is reached; from then on the figure stands still.
  double arrival_time_s() const { return path_length_m() / speed_m_s_; }

 private:
  std::vector<Eigen::Vector2d> waypoints_m_;
  std::vector<double> distance_at_m_;  // path length from the first waypoint to each waypoint
  double speed_m_s_;
  double arm_raise_rad_;
  double final_heading_rad_ = 0.0;  // along the last segment of non-zero length; 0 if none
};

}  // namespace safecell
