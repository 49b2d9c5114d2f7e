#pragma once
// The robot's pose for one frame set, from the smart buffer (joint_buffer.hpp), and when it may
// not be used.
//
// Robot removal takes the robot's silhouette at the exposure's joints, widened by a budget the
// pipeline was built with (FusionSettings::sync_error_s: sum over the joints of l_i v_max,i
// sync_error_s, removal_widening_m()). The buffer's error e_i carried to the robot by the lever
// arms, sum l_i e_i, must fit that budget; otherwise the removal could erase a person next to the
// arm.
//
// The choice for an unknown pose (no recent joints, an exposure outside the buffer, an error over
// the budget): the cycle publishes an all-forbidden map, and the robot stops. Without the pose the
// robot's own image cannot be told from a person's, and removing nothing would forbid the robot's
// own cells anyway: a stop either way, and this one says why.

#include <cstdint>
#include <string>
#include <vector>

#include "safecell/cspace/cspace_grid.hpp"
#include "safecell/link/joint_buffer.hpp"

namespace safecell {

struct RobotPoseAtExposure {
  bool known = false;
  std::vector<double> q;        // joints at the exposure (rad), when known
  double error_m = 0.0;         // sum over the joints of l_i * error_i
  std::string unknown_because;  // when not known, for the log and the stop report
};

// widening_budget_m: what the removal's widening allows for timing (not the padding).
RobotPoseAtExposure robot_pose_at_exposure(const JointBuffer& joints, std::uint64_t exposure_ns,
                                           const CspaceGrid& grid, double widening_budget_m);

}  // namespace safecell
