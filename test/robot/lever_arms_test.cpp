#include "safecell/robot/lever_arms.hpp"

#include <gtest/gtest.h>

#include "robot_fixtures.hpp"
#include "safecell/geometry/shape_bounds.hpp"
#include "safecell/robot/kinematics.hpp"
#include "safecell/robot/robot_error.hpp"
#include "safecell/test/property.hpp"

namespace safecell {
namespace {

ToolSpec flange_tool() { return ToolSpec{"flange", {}, Eigen::Vector3d::Zero()}; }

double distance_from_axis(const Eigen::Vector3d& point, const Eigen::Vector3d& origin,
                          const Eigen::Vector3d& axis) {
  const Eigen::Vector3d offset = point - origin;
  return (offset - axis.dot(offset) * axis).norm();
}

TEST(LeverArms, Rx160WithTheFlangeAsTool) {
  SAFECELL_REQUIRE_RX160(robot);
  const LeverArms arms = compute_lever_arms(robot, flange_tool());
  // Joint 1: offset 0.15 + upper arm 0.825 + forearm 0.625 + wrist 0.11 = 1.71 m;
  // joint 2: 0.825 + 0.625 + 0.11 = 1.56 m; joint 3: 0.625 + 0.11 = 0.735 m.
  EXPECT_NEAR(arms.tool_m[0], 1.71, 1.71 * 0.02);
  EXPECT_NEAR(arms.tool_m[1], 1.56, 1.56 * 0.02);
  EXPECT_NEAR(arms.tool_m[2], 0.735, 0.735 * 0.02);
  // The wrist: the flange 0.11 m from joints 4 and 5, on the axis of joint 6.
  EXPECT_NEAR(arms.tool_m[3], 0.11, 0.005);
  EXPECT_NEAR(arms.tool_m[4], 0.11, 0.005);
  EXPECT_NEAR(arms.tool_m[5], 0.0, 1e-9);
  for (std::size_t j = 0; j < 6; ++j)
    EXPECT_GE(arms.envelope_m[j], arms.tool_m[j]) << "joint " << j;
}

TEST(LeverArms, DefaultRobotByHand) {
  const LeverArms arms = compute_lever_arms(default_robot(), flange_tool());
  // 0.15 + 0.625 + 0.625 + 0.11 = 1.51; 0.625 + 0.625 + 0.11 = 1.36; 0.625 + 0.11 = 0.735.
  const double expected[] = {1.51, 1.36, 0.735, 0.11, 0.11, 0.0};
  for (std::size_t j = 0; j < 6; ++j) {
    EXPECT_GE(arms.tool_m[j], expected[j] - 1e-9) << "joint " << j;  // never below the truth
    EXPECT_LE(arms.tool_m[j], expected[j] * 1.005 + 1e-6) << "joint " << j;
  }
}

// No point of the robot, in any configuration, is farther from a joint's axis than l_i.
TEST(LeverArms, EnvelopeBoundsEveryPointInRandomConfigurations) {
  const RobotModel robot = default_robot();
  const ToolSpec tool{
      "flange",
      {PlacedShape{Cylinder{0.04, 0.2}, Eigen::Isometry3d(Eigen::Translation3d(0, 0, 0.1))}},
      Eigen::Vector3d(0, 0, 0.2)};
  const LeverArms arms = compute_lever_arms(robot, tool);
  test::PropertyRun run(300);
  for (int i = 0; i < run.iterations(); ++i) {
    std::vector<double> q;
    for (const auto& joint : robot.joints) {
      q.push_back(std::uniform_real_distribution<double>(joint.lower, joint.upper)(run.rng()));
    }
    const auto poses = link_poses(robot, q);
    const Eigen::Isometry3d flange = frame_pose(robot, q, "flange");
    for (std::size_t j = 0; j < robot.dof(); ++j) {
      const Eigen::Vector3d origin = poses[j].translation();
      const Eigen::Vector3d axis = poses[j].linear() * robot.joints[j].axis;
      double farthest = distance_from_axis(flange * tool.point_m, origin, axis);
      for (const auto& point :
           extreme_points(PlacedShape{tool.shapes[0].shape, flange * tool.shapes[0].pose})) {
        farthest = std::max(farthest, distance_from_axis(point, origin, axis));
      }
      for (std::size_t k = j; k < robot.dof(); ++k) {
        for (const auto& shape : robot.links[k].collision) {
          for (const auto& point :
               extreme_points(PlacedShape{shape.shape, poses[k] * shape.pose})) {
            farthest = std::max(farthest, distance_from_axis(point, origin, axis));
          }
        }
      }
      ASSERT_LE(farthest, arms.envelope_m[j] + 1e-9) << "joint " << j << " iteration " << i;
    }
  }
}

TEST(LeverArms, ToolFrameMustExistAndMove) {
  const RobotModel robot = default_robot();
  EXPECT_THROW(static_cast<void>(compute_lever_arms(robot, ToolSpec{"gripper", {}, {}})),
               RobotError);
  EXPECT_THROW(static_cast<void>(compute_lever_arms(robot, ToolSpec{"base_link", {}, {}})),
               RobotError);
}

}  // namespace
}  // namespace safecell
