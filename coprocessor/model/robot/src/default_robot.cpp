#include "safecell/robot/default_robot.hpp"

#include <string>

#include "safecell/robot/urdf_loader.hpp"

namespace safecell {

extern const char* const kDefaultRobotUrdf;  // generated from robots/rx130_class.urdf

std::string_view default_robot_urdf() { return kDefaultRobotUrdf; }

RobotModel default_robot() {
  // Primitives only: no mesh paths to resolve.
  return parse_urdf(std::string(default_robot_urdf()), kDefaultRobotSource, {});
}

}  // namespace safecell
