#include "safecell/link/robot_pose_at_exposure.hpp"

#include <sstream>

namespace safecell {

RobotPoseAtExposure robot_pose_at_exposure(const JointBuffer& joints, std::uint64_t exposure_ns,
                                           const CspaceGrid& grid, double widening_budget_m) {
  RobotPoseAtExposure pose;
  if (joints.joint_count() != grid.joint_count()) {
    pose.unknown_because = "the joint stream has " + std::to_string(joints.joint_count()) +
                           " joints, the grid " + std::to_string(grid.joint_count());
    return pose;
  }
  const JointsAtTime at = joints.at(exposure_ns);
  if (!at.known) {
    pose.unknown_because = at.unknown_because;
    return pose;
  }
  for (std::uint32_t j = 0; j < grid.joint_count(); ++j) {
    pose.error_m += grid.joint(j).l_m * at.error_rad[j];
  }
  if (pose.error_m > widening_budget_m) {
    std::ostringstream why;
    why << "the joints at the exposure are uncertain by " << pose.error_m * 1e3
        << " mm at the robot, over the removal's timing allowance of " << widening_budget_m * 1e3
        << " mm";
    pose.unknown_because = why.str();
    return pose;
  }
  pose.known = true;
  pose.q = at.position_rad;
  return pose;
}

}  // namespace safecell
