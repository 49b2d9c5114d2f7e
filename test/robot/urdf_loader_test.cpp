#include "safecell/robot/urdf_loader.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "robot_fixtures.hpp"
#include "safecell/robot/mesh_loader.hpp"
#include "safecell/robot/robot_error.hpp"
#include "two_joint_arm.hpp"

namespace safecell {
namespace {

using test::arm_with;
using test::error_of;
using test::expect_error;

TEST(UrdfLoader, ReadsTheChain) {
  const RobotModel robot = parse_urdf(arm_with(""), "arm.urdf", {});
  EXPECT_EQ(robot.name, "two");
  ASSERT_EQ(robot.dof(), 2u);
  EXPECT_EQ(robot.joints[1].name, "b");
  EXPECT_EQ(robot.joints[1].axis, Eigen::Vector3d::UnitY());
  EXPECT_EQ(robot.joints[1].lower, -2.0);
  EXPECT_EQ(robot.joints[1].max_speed, 2.0);
  EXPECT_EQ(robot.links[0].name, "upper");
  ASSERT_EQ(robot.links[0].collision.size(), 1u);
  EXPECT_TRUE(std::holds_alternative<Box>(robot.links[0].collision[0].shape));
}

TEST(UrdfLoader, FoldsFixedLinksIntoTheLinkTheyHangFrom) {
  const RobotModel robot =
      parse_urdf(arm_with(R"(<joint name="f" type="fixed"><parent link="lower"/><child link="tip"/>
                  <origin xyz="0 0 0.3"/></joint>
                  <link name="tip"><collision><geometry><sphere radius="0.05"/></geometry></collision></link>
                  <joint name="g" type="fixed"><parent link="upper"/><child link="camera_mount"/>
                  <origin xyz="0.1 0 0"/></joint>
                  <link name="camera_mount"><collision><geometry><sphere radius="0.02"/></geometry></collision></link>)"),
                 "arm.urdf", {});
  ASSERT_EQ(robot.dof(), 2u);
  ASSERT_EQ(robot.links[1].collision.size(), 2u);  // its cylinder and the tip's sphere 0.3 m out
  EXPECT_NEAR(robot.links[1].collision[1].pose.translation().z(), 0.3, 1e-12);
  ASSERT_EQ(robot.links[0].collision.size(), 2u);  // the side branch folds into "upper"
  EXPECT_NEAR(robot.frame("camera_mount")->pose.translation().x(), 0.1, 1e-12);
  EXPECT_EQ(robot.frame("tip")->link, 1);
}

TEST(UrdfLoader, RefusesWhatItCannotUse) {
  expect_error(error_of("<robot name='x'><link name='a'/>"), "not well-formed XML");
  expect_error(error_of(arm_with(R"(<joint name="s" type="spherical"><parent link="lower"/>
                                    <child link="ball"/></joint><link name="ball"/>)")),
               "not a valid URDF");
  expect_error(error_of(arm_with(R"(<joint name="fl" type="floating"><parent link="lower"/>
                                    <child link="free"/></joint><link name="free"/>)")),
               "floating and planar joints are not supported");
  expect_error(error_of(arm_with(R"(<joint name="finger" type="prismatic"><parent link="upper"/>
                                    <child link="side"/><axis xyz="1 0 0"/>
                                    <limit lower="0" upper="0.1" effort="1" velocity="1"/></joint>
                                    <link name="side"/>)"),
                        UrdfOptions{"lower", {}}),
               "only serial chains are supported");
  expect_error(error_of(arm_with(""), UrdfOptions{"gripper", {}}), "no link named 'gripper'");
  expect_error(error_of(arm_with(""), UrdfOptions{"base", {}}), "is the root link");
  // A link with two parents closes a loop.
  expect_error(error_of(arm_with(R"(<joint name="loop" type="fixed"><parent link="lower"/>
                                    <child link="upper"/></joint>)")),
               "loop");
  expect_error(error_of(arm_with(R"(<joint name="f" type="fixed"><parent link="lower"/>
                                    <child link="m"/></joint><link name="m"><collision><geometry>
                                    <mesh filename="no_such_mesh.stl"/></geometry></collision></link>)")),
               "mesh file");
  expect_error(error_of(arm_with(R"(<joint name="f" type="fixed"><parent link="lower"/>
                                    <child link="m"/></joint><link name="m"><collision><geometry>
                                    <mesh filename="package://robot/m.stl"/></geometry></collision></link>)")),
               "ROS package URI");
}

TEST(UrdfLoader, UnreadableFilesAndMeshes) {
  EXPECT_THROW(static_cast<void>(load_urdf_file("/nonexistent/robot.urdf")), RobotError);
  const auto garbage = std::filesystem::temp_directory_path() / "safecell-garbage.stl";
  std::ofstream(garbage) << "this is not a mesh";
  EXPECT_THROW(static_cast<void>(load_mesh(garbage)), RobotError);
  std::filesystem::remove(garbage);
}

TEST(UrdfLoader, Rx160WithMeshes) {
  SAFECELL_REQUIRE_RX160(robot);
  EXPECT_EQ(robot.name, "staubli_rx160");
  ASSERT_EQ(robot.dof(), 6u);
  EXPECT_EQ(robot.joints[0].name, "joint_1");
  EXPECT_NEAR(robot.joints[1].upper, 2.399828, 1e-9);
  for (const auto& link : robot.links) {
    ASSERT_EQ(link.collision.size(), 1u) << link.name;
    const auto& mesh = std::get<std::shared_ptr<const TriangleMesh>>(link.collision[0].shape);
    EXPECT_GT(mesh->triangles.size(), 100u) << link.name;
  }
  EXPECT_TRUE(robot.frame("tool0").has_value());
}

}  // namespace
}  // namespace safecell
