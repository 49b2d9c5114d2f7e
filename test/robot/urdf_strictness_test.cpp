// A URDF that loses a link's collision geometry, or a joint's offset, on the way into the model
// must be refused: what urdfdom cannot read, elements and attributes it would pass over, shapes of
// no size, a moving link without collision geometry, and files nested or sized beyond any robot.

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "robot_fixtures.hpp"
#include "safecell/robot/robot_error.hpp"
#include "safecell/robot/urdf_loader.hpp"
#include "two_joint_arm.hpp"

namespace safecell {
namespace {

using test::arm_with;
using test::error_of;
using test::expect_error;

// The two-joint arm (with `extra`) and the collision of link "upper" replaced.
std::string with_upper_collision(const std::string& collision, const std::string& extra = "") {
  std::string text = arm_with(extra);
  const std::string old =
      R"(<collision><geometry><box size="0.1 0.1 0.4"/></geometry></collision>)";
  return text.replace(text.find(old), old.size(), collision);
}

TEST(UrdfStrictness, ACollisionOriginThatCannotBeReadRefusesTheFile) {
  for (const std::string origin : {"garbage", "nan nan nan", "1 2", "1e999 0 0", "0 0 0 0"}) {
    SCOPED_TRACE(origin);
    const std::string message = error_of(
        with_upper_collision(R"(<collision><origin xyz=")" + origin +
                             R"("/><geometry><box size="0.1 0.1 0.4"/></geometry></collision>)"));
    expect_error(message, "not a valid URDF");
    expect_error(message, "[upper]");
    expect_error(message, "[" + origin.substr(0, origin.find(' ')));
  }
  // Control: the same element with a readable origin loads, its box where the origin puts it.
  const RobotModel robot = parse_urdf(
      with_upper_collision(
          R"(<collision><origin xyz="0 0 0.2"/><geometry><box size="0.1 0.1 0.4"/></geometry></collision>)"),
      "arm.urdf", {});
  ASSERT_EQ(robot.links[0].collision.size(), 1u);
  EXPECT_NEAR(robot.links[0].collision[0].pose.translation().z(), 0.2, 1e-12);
}

TEST(UrdfStrictness, ElementsAndAttributesTheLoaderWouldPassOverAreRefused) {
  expect_error(error_of(with_upper_collision(
                   R"(<colision><geometry><box size="0.1 0.1 0.4"/></geometry></colision>)")),
               "link 'upper': <link> holds an element <colision>, expected inertial, visual or "
               "collision");
  expect_error(
      error_of(with_upper_collision(
          R"(<collision><origin xzy="0 0 1"/><geometry><box size="1 1 1"/></geometry></collision>)")),
      "<origin> has an attribute 'xzy', expected only xyz or rpy");
  expect_error(
      error_of(with_upper_collision(
          R"(<collision><geometry><box size="1 1 1"/><sphere radius="1"/></geometry></collision>)")),
      "<geometry> holds 2 shapes");
  std::string misspelt_offset = arm_with("");
  misspelt_offset.replace(misspelt_offset.find(R"(<origin xyz="0 0 0.4"/>)"), 7, "<orgin");
  expect_error(error_of(misspelt_offset), "joint 'b': <joint> holds an element <orgin>");
  // The message names the line.
  EXPECT_NE(error_of(misspelt_offset).find("arm.urdf:14: "), std::string::npos)
      << error_of(misspelt_offset);
}

TEST(UrdfStrictness, ShapesOfNoSizeAreRefused) {
  expect_error(error_of(with_upper_collision(
                   R"(<collision><geometry><box size="0.1 0 0.4"/></geometry></collision>)")),
               "link 'upper': <box size> y is 0");
  expect_error(error_of(with_upper_collision(
                   R"(<collision><geometry><sphere radius="-1"/></geometry></collision>)")),
               "<sphere radius> is -1");
  expect_error(
      error_of(with_upper_collision(
          R"(<collision><geometry><cylinder radius="0.1" length="0"/></geometry></collision>)")),
      "<cylinder length> is 0");
}

TEST(UrdfStrictness, AMovingLinkWithoutCollisionGeometryIsRefusedUnlessAStandInIsNamed) {
  const std::string bare = with_upper_collision("");
  expect_error(error_of(bare), "link 'upper' moves but has no <collision> geometry");
  // A fixed link hung from it brings geometry: accepted.
  const RobotModel folded =
      parse_urdf(with_upper_collision("", R"(<joint name="g" type="fixed"><parent link="upper"/>
        <child link="mount"/></joint>
        <link name="mount"><collision><geometry><sphere radius="0.1"/></geometry></collision></link>)"),
                 "arm.urdf", {});
  ASSERT_EQ(folded.links[0].collision.size(), 1u);
  EXPECT_TRUE(std::holds_alternative<Sphere>(folded.links[0].collision[0].shape));

  Eigen::Isometry3d up = Eigen::Isometry3d::Identity();
  up.translation().z() = 0.2;
  const UrdfOptions stand_in{"", {{"upper", {PlacedShape{Box{{0.1, 0.1, 0.4}}, up}}}}};
  const RobotModel robot = parse_urdf(bare, "arm.urdf", {}, stand_in);
  ASSERT_EQ(robot.links[0].collision.size(), 1u);
  EXPECT_NEAR(robot.links[0].collision[0].pose.translation().z(), 0.2, 1e-12);

  expect_error(error_of(arm_with(""), stand_in), "has <collision> geometry, yet a stand-in");
  expect_error(error_of(bare, UrdfOptions{"", {{"uper", {PlacedShape{Sphere{0.1}, up}}}}}),
               "link 'uper', which is not on the chain");
}

TEST(UrdfStrictness, NestingAndSizeBeyondAnyRobotAreRefusedBeforeParsing) {
  constexpr int kDepth = 100000;  // TinyXML 1, urdfdom's parser, overflows its stack on this
  std::string deep = "<robot name='deep'>";
  for (int i = 0; i < kDepth; ++i) deep += "<a>";
  for (int i = 0; i < kDepth; ++i) deep += "</a>";
  deep += "</robot>";
  expect_error(error_of(deep), "elements nested deeper than 100");
  expect_error(error_of(std::string(17u << 20, ' ')), "bytes, expected at most 16777216");
  expect_error(error_of("<robot name='x'><link name='a'>"), "not well-formed XML");
  expect_error(error_of("<robt name='x'/>"), "the top element is not <robot>");
}

// The negative control on a real robot: one link's collision origin broken in the RX160's URDF.
TEST(UrdfStrictness, Rx160WithOneBrokenCollisionOriginIsRefused) {
  if (!std::filesystem::exists(test::rx160_urdf_path())) GTEST_SKIP() << "no RX160 model";
  std::ifstream file(test::rx160_urdf_path());
  std::stringstream text;
  text << file.rdbuf();
  std::string urdf = text.str();
  const std::string directory = test::rx160_urdf_path().parent_path().string();
  EXPECT_EQ(parse_urdf(urdf, "rx160.urdf", directory).dof(), 6u);  // as it is: loads
  const std::size_t link = urdf.find(R"(<link name="link_3">)");
  const std::size_t origin = urdf.find(R"(<origin xyz="0 0 0")", urdf.find("<collision>", link));
  ASSERT_NE(origin, std::string::npos);
  urdf.replace(origin, 19, R"(<origin xyz="0 0 O")");  // a letter O for a zero
  try {
    static_cast<void>(parse_urdf(urdf, "rx160.urdf", directory));
    FAIL() << "the broken RX160 loaded";
  } catch (const RobotError& error) {
    EXPECT_NE(std::string(error.what()).find("[link_3]"), std::string::npos) << error.what();
    EXPECT_NE(std::string(error.what()).find("[O]"), std::string::npos) << error.what();
  }
}

}  // namespace
}  // namespace safecell
