#include "safecell/robot/robot_parts.hpp"

namespace safecell {

const char* to_string(PartSplit split) {
  switch (split) {
    case PartSplit::kWholeRobot:
      return "whole-robot";
    case PartSplit::kPerLink:
      return "per-link";
    case PartSplit::kArmSegments:
      return "arm-segments";
  }
  return "unknown";
}

bool parse_part_split(const std::string& text, PartSplit& split) {
  for (const PartSplit candidate :
       {PartSplit::kWholeRobot, PartSplit::kPerLink, PartSplit::kArmSegments}) {
    if (text == to_string(candidate)) {
      split = candidate;
      return true;
    }
  }
  return false;
}

std::vector<RobotPart> robot_parts(const RobotModel& robot, PartSplit split) {
  const std::size_t bodies = robot.dof() + 1;
  if (split == PartSplit::kWholeRobot) return {RobotPart{"robot", 0, bodies}};
  if (split == PartSplit::kArmSegments && robot.dof() >= 3) {
    // The base stands still; the upper arm moves with joints 1-2 only; the forearm and the wrist
    // with all. Each segment's envelope is then the union of far fewer sweeps.
    return {
        RobotPart{"base", 0, 1}, RobotPart{"upper arm (links 1-2)", 1, 3},
        RobotPart{"forearm and wrist (links 3-" + std::to_string(robot.dof()) + ")", 3, bodies}};
  }
  std::vector<RobotPart> parts{RobotPart{"base", 0, 1}};
  for (std::size_t link = 0; link < robot.dof(); ++link) {
    parts.push_back(RobotPart{robot.links[link].name.empty() ? "link " + std::to_string(link + 1)
                                                             : robot.links[link].name,
                              link + 1, link + 2});
  }
  return parts;
}

}  // namespace safecell
