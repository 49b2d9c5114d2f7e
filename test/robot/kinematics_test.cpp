#include "safecell/robot/kinematics.hpp"

#include <gtest/gtest.h>

#include <numbers>

#include "robot_fixtures.hpp"

namespace safecell {
namespace {

constexpr double kHalfPi = std::numbers::pi / 2.0;

Eigen::Vector3d flange_at(const RobotModel& model, const std::vector<double>& q) {
  return frame_pose(model, q, "flange").translation();
}

void expect_near(const Eigen::Vector3d& actual, const Eigen::Vector3d& expected) {
  EXPECT_LT((actual - expected).norm(), 1e-6)
      << "actual " << actual.transpose() << ", expected " << expected.transpose();
}

// Default arm: shoulder 0.55 m up with a 0.15 m offset, upper arm 0.625, forearm 0.625,
// wrist to flange 0.11 m.
TEST(Kinematics, DefaultRobotByHand) {
  const RobotModel robot = default_robot();
  ASSERT_EQ(robot.dof(), 6u);
  // Stretched upwards: (0.15, 0, 0.55 + 0.625 + 0.625 + 0.11) = (0.15, 0, 1.91).
  expect_near(flange_at(robot, {0, 0, 0, 0, 0, 0}), {0.15, 0.0, 1.91});
  // Joint 1 at +90 deg turns the offset onto +y.
  expect_near(flange_at(robot, {kHalfPi, 0, 0, 0, 0, 0}), {0.0, 0.15, 1.91});
  // Joint 2 at +90 deg (about +y: z turns into x): the arm lies along +x at shoulder height,
  // (0.15 + 1.36, 0, 0.55).
  expect_near(flange_at(robot, {0, kHalfPi, 0, 0, 0, 0}), {1.51, 0.0, 0.55});
  // Joint 3 at +90 deg: forearm along +x from the elbow at (0.15, 0, 1.175).
  expect_near(flange_at(robot, {0, 0, kHalfPi, 0, 0, 0}), {0.885, 0.0, 1.175});
  // Joint 5 at +90 deg: the flange sticks out 0.11 m along +x from the wrist at (0.15, 0, 1.8).
  expect_near(flange_at(robot, {0, 0, 0, 0, kHalfPi, 0}), {0.26, 0.0, 1.8});
  // Joint 4 at +90 deg then joint 5 at +90 deg: the flange points along +y instead.
  expect_near(flange_at(robot, {0, 0, 0, kHalfPi, kHalfPi, 0}), {0.15, 0.11, 1.8});
}

TEST(Kinematics, Rx160ByHand) {
  SAFECELL_REQUIRE_RX160(robot);
  ASSERT_EQ(robot.dof(), 6u);
  // RX160: shoulder 0.55 m, offset 0.15, upper arm 0.825, forearm 0.625, wrist 0.11.
  expect_near(flange_at(robot, {0, 0, 0, 0, 0, 0}), {0.15, 0.0, 2.11});
  expect_near(flange_at(robot, {0, kHalfPi, 0, 0, 0, 0}), {1.71, 0.0, 0.55});
  expect_near(flange_at(robot, {0, 0, -kHalfPi, 0, 0, 0}), {0.15 - 0.735, 0.0, 1.375});
}

TEST(Kinematics, ShapesFollowTheirLinks) {
  const RobotModel robot = default_robot();
  const std::vector<double> q{0.3, -0.4, 0.9, 1.0, -0.5, 2.0};
  const auto poses = link_poses(robot, q);
  Eigen::Isometry3d base = Eigen::Isometry3d::Identity();
  base.translation() = Eigen::Vector3d(1.0, -2.0, 0.0);
  const auto shapes = collision_shapes_at(robot, q, base);
  // Base shapes first, then each link's in order; the last is the flange disc on link_6.
  ASSERT_EQ(shapes.size(), robot.base.collision.size() + 8u);
  const PlacedShape& flange_disc = shapes.back();
  const Eigen::Isometry3d expected = base * poses[5] * robot.links[5].collision[0].pose;
  EXPECT_LT((flange_disc.pose.matrix() - expected.matrix()).norm(), 1e-12);
  EXPECT_THROW(static_cast<void>(link_poses(robot, {0.0})), std::invalid_argument);
}

TEST(Kinematics, VisualShapesFallBackToCollisionShapes) {
  const RobotModel robot = default_robot();  // primitives for collision only
  const std::vector<double> q{0.1, 0.2, 0.3, 0.4, 0.5, 0.6};
  EXPECT_EQ(visual_shapes_at(robot, q).size(), collision_shapes_at(robot, q).size());
}

TEST(Kinematics, Rx160VisualMeshesDifferFromCollisionMeshes) {
  SAFECELL_REQUIRE_RX160(robot);
  const std::vector<double> q(6, 0.3);
  const auto visual = visual_shapes_at(robot, q);
  const auto collision = collision_shapes_at(robot, q);
  ASSERT_EQ(visual.size(), collision.size());
  const auto& visual_mesh = std::get<std::shared_ptr<const TriangleMesh>>(visual.back().shape);
  const auto& collision_mesh =
      std::get<std::shared_ptr<const TriangleMesh>>(collision.back().shape);
  EXPECT_NE(visual_mesh, collision_mesh);
  EXPECT_LT((visual.back().pose.matrix() - collision.back().pose.matrix()).norm(), 1e-12);
}

}  // namespace
}  // namespace safecell
