#pragma once
// The tool the robot carries: collision shapes and a tool centre point, hung from a named frame
// of the robot (a link such as "flange"). A different tool is a different robot geometry: it needs
// its own grid and look-up tables (the paper, Section 4.1).

#include <Eigen/Core>
#include <string>
#include <vector>

#include "safecell/geometry/shape.hpp"
#include "safecell/robot/robot_model.hpp"

namespace safecell {

struct ToolSpec {
  std::string frame;                                  // empty: the last movable link
  std::vector<PlacedShape> shapes;                    // in that frame
  Eigen::Vector3d point_m = Eigen::Vector3d::Zero();  // tool centre point, in that frame
};

// Adds the tool's shapes to the collision geometry of the link its frame belongs to, so that
// kinematics, rendering and the ground truth all carry the tool. Throws RobotError when the
// frame does not exist or is part of the base.
void attach_tool(RobotModel& model, const ToolSpec& tool);

// The frame the tool hangs from, checked as attach_tool() does.
NamedFrame tool_frame(const RobotModel& model, const ToolSpec& tool);

}  // namespace safecell
