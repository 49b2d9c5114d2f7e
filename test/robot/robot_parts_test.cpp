#include "safecell/robot/robot_parts.hpp"

#include <gtest/gtest.h>

#include "safecell/robot/default_robot.hpp"
#include "safecell/robot/kinematics.hpp"

namespace safecell {
namespace {

// The parts of a split cover every body once, in order.
void expect_partition(const RobotModel& robot, const std::vector<RobotPart>& parts) {
  ASSERT_FALSE(parts.empty());
  std::size_t next = 0;
  for (const RobotPart& part : parts) {
    EXPECT_EQ(part.first_body, next) << part.name;
    EXPECT_GT(part.end_body, part.first_body) << part.name;
    EXPECT_FALSE(part.name.empty());
    next = part.end_body;
  }
  EXPECT_EQ(next, robot.dof() + 1);
}

TEST(RobotParts, EverySplitCoversEveryBodyOnce) {
  const RobotModel robot = default_robot();
  for (const PartSplit split : {PartSplit::kWholeRobot, PartSplit::kPerLink,
                                PartSplit::kArmSegments, PartSplit::kLinksAndWrist}) {
    SCOPED_TRACE(to_string(split));
    expect_partition(robot, robot_parts(robot, split));
  }
  EXPECT_EQ(robot_parts(robot, PartSplit::kWholeRobot).size(), 1U);
  EXPECT_EQ(robot_parts(robot, PartSplit::kPerLink).size(), robot.dof() + 1);
  const auto segments = robot_parts(robot, PartSplit::kArmSegments);
  ASSERT_EQ(segments.size(), 3U);
  EXPECT_EQ(segments[1].first_body, 1U);
  EXPECT_EQ(segments[1].end_body, 3U);
  // Links 1-3 on their own, the wrist's three links as one part.
  const auto links_and_wrist = robot_parts(robot, PartSplit::kLinksAndWrist);
  ASSERT_EQ(links_and_wrist.size(), 5U);
  for (std::size_t body = 0; body < 4; ++body) {
    EXPECT_EQ(links_and_wrist[body].first_body, body);
    EXPECT_EQ(links_and_wrist[body].end_body, body + 1);
  }
  EXPECT_EQ(links_and_wrist[4].first_body, 4U);
  EXPECT_EQ(links_and_wrist[4].end_body, 7U);
  EXPECT_EQ(links_and_wrist[4].name, "wrist (links 4-6)");
}

TEST(RobotParts, ShortArmsAreCutPerLink) {
  RobotModel robot = default_robot();
  robot.joints.resize(2);
  robot.links.resize(2);
  const auto parts = robot_parts(robot, PartSplit::kArmSegments);
  expect_partition(robot, parts);
  EXPECT_EQ(parts.size(), 3U);
  // A wrist of one link is that link.
  robot = default_robot();
  robot.joints.resize(4);
  robot.links.resize(4);
  const auto four = robot_parts(robot, PartSplit::kLinksAndWrist);
  expect_partition(robot, four);
  EXPECT_EQ(four.size(), 5U);
  EXPECT_EQ(four.back().first_body, 4U);
}

TEST(RobotParts, NamesReadBackAndUnknownNamesAreRefused) {
  for (const PartSplit split : {PartSplit::kWholeRobot, PartSplit::kPerLink,
                                PartSplit::kArmSegments, PartSplit::kLinksAndWrist}) {
    PartSplit read = PartSplit::kWholeRobot;
    ASSERT_TRUE(parse_part_split(to_string(split), read));
    EXPECT_EQ(read, split);
  }
  PartSplit untouched = PartSplit::kPerLink;
  EXPECT_FALSE(parse_part_split("per-joint", untouched));
  EXPECT_EQ(untouched, PartSplit::kPerLink);
  EXPECT_TRUE(is_part_split(PartSplit::kLinksAndWrist));
  EXPECT_FALSE(is_part_split(static_cast<PartSplit>(0)));
  EXPECT_FALSE(is_part_split(static_cast<PartSplit>(5)));
  EXPECT_EQ(part_split_names(), "per-link, links-and-wrist, arm-segments or whole-robot");
}

TEST(RobotParts, ThePartsShapesAreTheRobotsShapes) {
  const RobotModel robot = default_robot();
  const std::vector<double> q{0.3, -0.4, 1.1, 0.2, -0.7, 0.5};
  const auto whole = collision_shapes_at(robot, q);
  std::size_t count = 0;
  for (const RobotPart& part : robot_parts(robot, PartSplit::kPerLink)) {
    const auto shapes = collision_shapes_at(robot, q, Eigen::Isometry3d::Identity(),
                                            BodyRange{part.first_body, part.end_body});
    for (const auto& shape : shapes) {
      ASSERT_LT(count, whole.size());
      EXPECT_TRUE(shape.pose.isApprox(whole[count].pose)) << part.name;
      ++count;
    }
  }
  EXPECT_EQ(count, whole.size());
  EXPECT_TRUE(
      collision_shapes_at(robot, q, Eigen::Isometry3d::Identity(), BodyRange{3, 3}).empty());
}

}  // namespace
}  // namespace safecell
