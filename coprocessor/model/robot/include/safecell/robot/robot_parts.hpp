#pragma once
// The robot cut into parts for the camera vote (DESIGN.md §3, "Fusion"): a configuration can only
// collide where one part meets the obstacle, and that part's silhouette holds the obstacle in
// every camera that sees it. So the vote is taken per part - critical when, for some part, at
// least k cameras see an obstacle inside that part's silhouette - which is exactly as safe as the
// vote over the whole robot and removes the phantoms where one camera's obstacle touches the
// wrist and another's the elbow.
//
// Bodies are numbered as the envelope numbers them: 0 is the base, body j + 1 is link j. A part
// is a run of consecutive bodies; the parts of a split cover every body once, in order.

#include <cstdint>
#include <string>
#include <vector>

#include "safecell/robot/robot_model.hpp"

namespace safecell {

struct RobotPart {
  std::string name;
  std::size_t first_body = 0;
  std::size_t end_body = 0;  // one past the last
};

enum class PartSplit : std::uint32_t {
  kWholeRobot = 1,  // one part: the vote of the paper
  kPerLink = 2,     // the base and every link on its own
  kArmSegments =
      3,  // the base | the links of joints 1-2 | the rest (a cell file that does not say)
  // The base and links 1-3 each on its own, the wrist (links 4 to the last) as one part: the
  // vote per link where it splits the arm, at a fraction of its tables (the wrist's links are
  // small and overlap, and their union's sets are far more compact than each one's).
  kLinksAndWrist = 4,
};

const char* to_string(PartSplit split);
// Reads a name of to_string() into `split`; false for anything else.
bool parse_part_split(const std::string& text, PartSplit& split);
// Whether `split` is one of the splits above (a value cast from a number may be none).
[[nodiscard]] bool is_part_split(PartSplit split);
// The names parse_part_split() reads, for messages: "per-link, links-and-wrist, ... or ...".
[[nodiscard]] std::string part_split_names();

// The parts of `robot` for `split`. Arm segments need at least 3 joints and links and wrist at
// least 5; with fewer the robot is cut per link.
[[nodiscard]] std::vector<RobotPart> robot_parts(const RobotModel& robot, PartSplit split);

}  // namespace safecell
