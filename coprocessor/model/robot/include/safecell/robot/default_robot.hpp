#pragma once
// The project's own RX130-class 6-axis arm (robots/rx130_class.urdf, compiled in): the robot of
// the paper's experiments, described from public kinematic facts with primitive collision shapes.

#include <string_view>

#include "safecell/robot/robot_model.hpp"

namespace safecell {

inline constexpr const char* kDefaultRobotSource = "built-in RX130-class arm";

std::string_view default_robot_urdf();
RobotModel default_robot();

}  // namespace safecell
