#include "safecell/robot/robot_parts.hpp"

#include <algorithm>
#include <iterator>

namespace safecell {

const char* to_string(PartSplit split) {
  switch (split) {
    case PartSplit::kWholeRobot:
      return "whole-robot";
    case PartSplit::kPerLink:
      return "per-link";
    case PartSplit::kArmSegments:
      return "arm-segments";
    case PartSplit::kLinksAndWrist:
      return "links-and-wrist";
  }
  return "unknown";
}

namespace {

constexpr PartSplit kSplits[] = {PartSplit::kPerLink, PartSplit::kLinksAndWrist,
                                 PartSplit::kArmSegments, PartSplit::kWholeRobot};

// Link `link` (0-based: moved by joints 0..link) as a part of its own.
RobotPart link_part(const RobotModel& robot, std::size_t link) {
  return RobotPart{
      robot.links[link].name.empty() ? "link " + std::to_string(link + 1) : robot.links[link].name,
      link + 1, link + 2};
}

}  // namespace

bool parse_part_split(const std::string& text, PartSplit& split) {
  for (const PartSplit candidate : kSplits) {
    if (text == to_string(candidate)) {
      split = candidate;
      return true;
    }
  }
  return false;
}

bool is_part_split(PartSplit split) {
  return std::find(std::begin(kSplits), std::end(kSplits), split) != std::end(kSplits);
}

std::string part_split_names() {
  std::string names;
  for (std::size_t i = 0; i < std::size(kSplits); ++i) {
    if (i > 0) names += i + 1 == std::size(kSplits) ? " or " : ", ";
    names += to_string(kSplits[i]);
  }
  return names;
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
  // The wrist's links start at joint 4 (index 3); with fewer than 2 of them there is none to join.
  constexpr std::size_t kWristLink = 3;
  const bool wrist = split == PartSplit::kLinksAndWrist && robot.dof() >= kWristLink + 2;
  std::vector<RobotPart> parts{RobotPart{"base", 0, 1}};
  for (std::size_t link = 0; link < (wrist ? kWristLink : robot.dof()); ++link) {
    parts.push_back(link_part(robot, link));
  }
  if (wrist) {
    parts.push_back(RobotPart{
        "wrist (links " + std::to_string(kWristLink + 1) + "-" + std::to_string(robot.dof()) + ")",
        kWristLink + 1, bodies});
  }
  return parts;
}

}  // namespace safecell
