#include "safecell/closed_loop/demo_world.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace safecell {
namespace {

constexpr double kWalk_m_s = 1.2;
constexpr double kStand_s = 4.0;  // standing next to the arm, reaching towards it
// Where the person stands: 1.9 m from the base, just outside the arm's sweep (it reaches 1.35 m
// there); reaching out, their hand comes into it.
Eigen::Vector2d stand_at() { return {1.65, -0.9}; }

// A configuration inside the grid: each joint clamped a little inside its range.
std::vector<double> inside(const CspaceGrid& grid, std::vector<double> q) {
  q.resize(grid.joint_count(), 0.0);
  for (std::uint32_t j = 0; j < grid.joint_count(); ++j) {
    const JointSpec& joint = grid.joint(j);
    const double margin = 0.01 * (joint.hi_rad - joint.lo_rad);
    q[j] = std::clamp(q[j], joint.lo_rad + margin, joint.hi_rad - margin);
  }
  return q;
}

Eigen::Vector2d corner(const CellModel& cell, double sx, double sy) {
  return {sx * (cell.config.size_m[0] / 2.0 - 0.3), sy * (cell.config.size_m[1] / 2.0 - 0.3)};
}

}  // namespace

DemoWorld::DemoWorld(const CellModel& cell, const CspaceGrid& grid, double person_enters_s)
    : start_rad_(inside(grid, {1.2, 0.5, 0.9, 0.0, 0.6, 0.0})),
      goals_rad_{inside(grid, {-1.2, 0.5, 0.9, 0.0, 0.6, 0.0}),
                 inside(grid, {1.2, 0.5, 0.9, 0.0, 0.6, 0.0})},
      enters_s_(person_enters_s),
      approach_({corner(cell, 1, -1), stand_at()}, kWalk_m_s),
      leave_({stand_at(), corner(cell, 1, 1)}, kWalk_m_s),
      stand_s_(kStand_s) {}

double DemoWorld::person_leaves_s() const {
  return enters_s_ + approach_.arrival_time_s() + stand_s_ + leave_.arrival_time_s();
}

std::optional<HumanPose> DemoWorld::person_at(double time_s) const {
  const double t = time_s - enters_s_;
  if (t < 0.0 || time_s > person_leaves_s()) return std::nullopt;
  if (t <= approach_.arrival_time_s()) return approach_.pose_at(t);
  const double standing = t - approach_.arrival_time_s();
  if (standing <= stand_s_) {
    HumanPose pose = approach_.pose_at(approach_.arrival_time_s());
    pose.heading_rad = std::atan2(-stand_at().y(), -stand_at().x());  // facing the robot's base
    pose.gait_amplitude = 0.0;
    // The arm comes up over the first second and stays out, reaching towards the robot.
    pose.right_arm_reach_rad = std::min(1.0, standing) * std::numbers::pi / 2.0;
    return pose;
  }
  return leave_.pose_at(standing - stand_s_);
}

}  // namespace safecell
