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
  for (const PartSplit split :
       {PartSplit::kWholeRobot, PartSplit::kPerLink, PartSplit::kArmSegments}) {
    SCOPED_TRACE(to_string(split));
    expect_partition(robot, robot_parts(robot, split));
  }
  EXPECT_EQ(robot_parts(robot, PartSplit::kWholeRobot).size(), 1U);
  EXPECT_EQ(robot_parts(robot, PartSplit::kPerLink).size(), robot.dof() + 1);
  const auto segments = robot_parts(robot, PartSplit::kArmSegments);
  ASSERT_EQ(segments.size(), 3U);
  EXPECT_EQ(segments[1].first_body, 1U);
  EXPECT_EQ(segments[1].end_body, 3U);
}

TEST(RobotParts, ShortArmsAreCutPerLink) {
  RobotModel robot = default_robot();
  robot.joints.resize(2);
  robot.links.resize(2);
  const auto parts = robot_parts(robot, PartSplit::kArmSegments);
  expect_partition(robot, parts);
  EXPECT_EQ(parts.size(), 3U);
}

TEST(RobotParts, NamesReadBackAndUnknownNamesAreRefused) {
  for (const PartSplit split :
       {PartSplit::kWholeRobot, PartSplit::kPerLink, PartSplit::kArmSegments}) {
    PartSplit read = PartSplit::kWholeRobot;
    ASSERT_TRUE(parse_part_split(to_string(split), read));
    EXPECT_EQ(read, split);
  }
  PartSplit untouched = PartSplit::kPerLink;
  EXPECT_FALSE(parse_part_split("per-joint", untouched));
  EXPECT_EQ(untouched, PartSplit::kPerLink);
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
