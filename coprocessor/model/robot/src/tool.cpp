#include "safecell/robot/tool.hpp"

#include "safecell/robot/robot_error.hpp"

namespace safecell {

NamedFrame tool_frame(const RobotModel& model, const ToolSpec& tool) {
  if (model.dof() == 0) throw RobotError(model.source + ": the robot has no movable joint");
  const std::string name = tool.frame.empty() ? model.links.back().name : tool.frame;
  const auto frame = model.frame(name);
  if (!frame) {
    throw RobotError(model.source + ": the tool hangs from '" + name +
                     "', which is not a link of the robot");
  }
  if (frame->link < 0) {
    throw RobotError(model.source + ": the tool hangs from '" + name +
                     "', which does not move (it is part of the base)");
  }
  return *frame;
}

void attach_tool(RobotModel& model, const ToolSpec& tool) {
  const NamedFrame frame = tool_frame(model, tool);
  RobotLink& link = model.links[static_cast<std::size_t>(frame.link)];
  for (const auto& shape : tool.shapes) {
    link.collision.push_back(PlacedShape{shape.shape, frame.pose * shape.pose});
  }
}

}  // namespace safecell
