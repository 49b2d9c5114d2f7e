#pragma once
// l_i of every joint: the largest distance from joint i's axis to any point of the robot that
// joint i moves, over every position of the joints after it. This is the l_i of the max-move grid
// (DESIGN.md §3): one cell step along joint i then moves no such point by more than m_max.
//
// Method (conservative, never below the true value): working from the tool back to the base, the
// points a joint moves are kept as a profile of (axial position, largest radius) about its axis;
// the joint before sees that profile as circles swept about the later axis (a full turn, which
// covers any joint range), sampled finely with the sampling error added to every radius.

#include <vector>

#include "safecell/robot/robot_model.hpp"
#include "safecell/robot/tool.hpp"

namespace safecell {

struct LeverArms {
  // The paper's l_i: the farthest the tool (centre point and shapes) gets from axis i.
  std::vector<double> tool_m;
  // Also every collision shape of the links joint i moves: the l_i the grid uses.
  std::vector<double> envelope_m;
};

// Throws RobotError when the tool's frame does not exist or does not move.
LeverArms compute_lever_arms(const RobotModel& model, const ToolSpec& tool);

}  // namespace safecell
