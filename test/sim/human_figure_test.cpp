#include "safecell/sim/human_figure.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <utility>

#include "safecell/test/property.hpp"

namespace safecell {
namespace {

constexpr double kPi = std::numbers::pi;

const PlacedShape& part(const std::vector<PlacedShape>& shapes, HumanPart which) {
  return shapes.at(static_cast<std::size_t>(which));
}

// The end points of a capsule's axis in the cell frame, lower one first.
std::pair<Eigen::Vector3d, Eigen::Vector3d> axis_ends(const PlacedShape& placed) {
  const auto& capsule = std::get<Capsule>(placed.shape);
  const Eigen::Vector3d a = placed.pose * Eigen::Vector3d(0.0, 0.0, -capsule.length_m / 2.0);
  const Eigen::Vector3d b = placed.pose * Eigen::Vector3d(0.0, 0.0, capsule.length_m / 2.0);
  return a.z() <= b.z() ? std::pair{a, b} : std::pair{b, a};
}

struct Extent {
  double low_m = std::numeric_limits<double>::infinity();
  double high_m = -std::numeric_limits<double>::infinity();
};

// Lowest and highest point of the figure, exactly (capsules and the sphere only).
Extent z_extent(const std::vector<PlacedShape>& shapes) {
  Extent extent;
  for (const PlacedShape& placed : shapes) {
    double low_m = 0.0;
    double high_m = 0.0;
    if (const auto* sphere = std::get_if<Sphere>(&placed.shape)) {
      low_m = placed.pose.translation().z() - sphere->radius_m;
      high_m = placed.pose.translation().z() + sphere->radius_m;
    } else {
      const auto [lower, upper] = axis_ends(placed);
      const double radius_m = std::get<Capsule>(placed.shape).radius_m;
      low_m = lower.z() - radius_m;
      high_m = upper.z() + radius_m;
    }
    extent.low_m = std::min(extent.low_m, low_m);
    extent.high_m = std::max(extent.high_m, high_m);
  }
  return extent;
}

HumanPose standing() {
  HumanPose pose;
  pose.gait_amplitude = 0.0;
  return pose;
}

TEST(HumanFigure, StandingFigureIsOneSeventyFiveTallOnTheFloor) {
  const Extent extent = z_extent(human_shapes(standing()));
  EXPECT_NEAR(extent.high_m, 1.75, 1e-12);
  EXPECT_NEAR(extent.low_m, 0.0, 1e-12);
}

TEST(HumanFigure, IsAHeadSphereAndNineCapsulesOfHumanGirth) {
  const std::vector<PlacedShape> shapes = human_shapes(HumanPose{});
  ASSERT_EQ(shapes.size(), kHumanPartCount);
  EXPECT_DOUBLE_EQ(std::get<Sphere>(part(shapes, HumanPart::kHead).shape).radius_m, 0.11);
  EXPECT_DOUBLE_EQ(std::get<Capsule>(part(shapes, HumanPart::kTorso).shape).radius_m, 0.15);
  for (std::size_t i = 2; i < kHumanPartCount; ++i) {
    const auto* limb = std::get_if<Capsule>(&shapes[i].shape);
    ASSERT_NE(limb, nullptr) << "part " << i;
    EXPECT_GE(limb->radius_m, 0.05) << "part " << i;
    EXPECT_LE(limb->radius_m, 0.08) << "part " << i;
    EXPECT_GT(limb->length_m, 0.3) << "part " << i;
  }
}

TEST(HumanFigure, ShouldersAreFortyCentimetresApart) {
  const std::vector<PlacedShape> shapes = human_shapes(standing());
  const Eigen::Vector3d left = axis_ends(part(shapes, HumanPart::kLeftUpperArm)).second;
  const Eigen::Vector3d right = axis_ends(part(shapes, HumanPart::kRightUpperArm)).second;
  EXPECT_NEAR((left - right).norm(), 0.40, 1e-12);
  EXPECT_NEAR(left.z(), 1.43, 1e-12);
  EXPECT_GT(left.y(), right.y());  // heading 0 faces +x, so the figure's left is +y
}

TEST(HumanFigure, HeightAndFeetHoldAtEveryGaitPhase) {
  test::PropertyRun run(400);
  std::uniform_real_distribution<double> phase(0.0, 2.0 * kPi), place(-5.0, 5.0), turn(-kPi, kPi);
  for (int i = 0; i < run.iterations(); ++i) {
    HumanPose pose;
    // Every degree of the cycle once, then random phases.
    pose.gait_phase_rad = i < 360 ? i * kPi / 180.0 : phase(run.rng());
    pose.position_m = {place(run.rng()), place(run.rng())};
    pose.heading_rad = turn(run.rng());
    const Extent extent = z_extent(human_shapes(pose));
    EXPECT_GE(extent.high_m, 1.70) << "phase " << pose.gait_phase_rad;
    EXPECT_LE(extent.high_m, 1.80) << "phase " << pose.gait_phase_rad;
    EXPECT_LE(std::abs(extent.low_m), 0.02) << "phase " << pose.gait_phase_rad;
  }
}

TEST(HumanFigure, LegsAndArmsSwingByHand) {
  HumanPose pose;
  pose.gait_phase_rad = kPi / 2.0;  // left thigh at its forward extreme, both knees straight
  const std::vector<PlacedShape> shapes = human_shapes(pose);
  // Thighs at +-0.3 rad; leg 0.43 + 0.44 = 0.87 m to the sole cap's centre:
  // hip height 0.87 cos 0.3 + 0.06 = 0.891142745539277 m, foot 0.87 sin 0.3 = 0.257102579795366 m
  // forward (left) and back (right) of the hips, both soles on the floor.
  const Eigen::Vector3d left_sole = axis_ends(part(shapes, HumanPart::kLeftShank)).first;
  const Eigen::Vector3d right_sole = axis_ends(part(shapes, HumanPart::kRightShank)).first;
  EXPECT_NEAR(left_sole.x(), 0.257102579795366, 1e-12);
  EXPECT_NEAR(left_sole.y(), 0.09, 1e-12);
  EXPECT_NEAR(left_sole.z(), 0.06, 1e-12);
  EXPECT_NEAR(right_sole.x(), -0.257102579795366, 1e-12);
  EXPECT_NEAR(right_sole.z(), 0.06, 1e-12);
  const Eigen::Vector3d hip = axis_ends(part(shapes, HumanPart::kLeftThigh)).second;
  EXPECT_NEAR(hip.z(), 0.891142745539277, 1e-12);
  // The head sinks with the hips: 1.75 - 0.93 + 0.891142745539277.
  EXPECT_NEAR(z_extent(shapes).high_m, 1.711142745539277, 1e-12);
  // Each arm swings against its own side's leg: the left elbow is behind the shoulder.
  const auto [left_elbow, left_shoulder] = axis_ends(part(shapes, HumanPart::kLeftUpperArm));
  EXPECT_NEAR(left_elbow.x(), 0.33 * std::sin(-0.25), 1e-12);
  EXPECT_LT(left_elbow.x(), left_shoulder.x());
  EXPECT_GT(axis_ends(part(shapes, HumanPart::kRightUpperArm)).first.x(), 0.0);
}

TEST(HumanFigure, RaisedArmsReachAlongTheHeading) {
  HumanPose pose = standing();
  pose.position_m = {2.0, 3.0};
  pose.heading_rad = kPi / 2.0;  // facing +y, so the figure's left is -x
  pose.arm_raise_rad = kPi / 2.0;
  const std::vector<PlacedShape> shapes = human_shapes(pose);
  // Upper arm horizontal, forearm 0.2 rad further up: the fingertip cap's centre lies
  // 0.33 + 0.39 cos 0.2 = 0.712225965358084 m ahead of the shoulder and
  // 0.39 sin 0.2 = 0.0774810390100738 m above it; the shoulders are at (2 -+ 0.2, 3, 1.43).
  for (const auto& [forearm, x_m] :
       {std::pair{HumanPart::kLeftForearm, 1.8}, std::pair{HumanPart::kRightForearm, 2.2}}) {
    const Eigen::Vector3d fingertip = axis_ends(part(shapes, forearm)).second;
    EXPECT_NEAR(fingertip.x(), x_m, 1e-12);
    EXPECT_NEAR(fingertip.y(), 3.712225965358084, 1e-12);
    EXPECT_NEAR(fingertip.z(), 1.507481039010074, 1e-12);
  }
  // The body stays where it stands.
  const Eigen::Vector3d pelvis = axis_ends(part(shapes, HumanPart::kTorso)).first;
  EXPECT_NEAR(pelvis.x(), 2.0, 1e-12);
  EXPECT_NEAR(pelvis.y(), 3.0, 1e-12);
}

}  // namespace
}  // namespace safecell
