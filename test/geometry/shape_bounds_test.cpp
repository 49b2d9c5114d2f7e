#include "safecell/geometry/shape_bounds.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace safecell {
namespace {

TEST(ShapeBounds, BoundingRadiusByHand) {
  // Box 0.6 x 0.8 x 0 -> half diagonal 0.5.
  EXPECT_DOUBLE_EQ(bounding_radius_m(Box{{0.6, 0.8, 0.0}}), 0.5);
  EXPECT_DOUBLE_EQ(bounding_radius_m(Sphere{0.25}), 0.25);
  // Cylinder r = 0.3, length 0.8: corner of the profile at (0.3, 0.4) -> 0.5.
  EXPECT_DOUBLE_EQ(bounding_radius_m(Cylinder{0.3, 0.8}), 0.5);
  EXPECT_DOUBLE_EQ(bounding_radius_m(Capsule{0.1, 0.6}), 0.4);
  auto mesh = std::make_shared<TriangleMesh>();
  mesh->vertices = {{0, 0, 0}, {3, 4, 0}, {0, 1, 0}};
  EXPECT_DOUBLE_EQ(bounding_radius_m(std::shared_ptr<const TriangleMesh>(mesh)), 5.0);
}

TEST(ShapeBounds, ExtremePointsReachTheFarthestPointFromALine) {
  // A cylinder of radius 0.1 along x, centred 2 m up the z axis: its farthest point from the
  // z axis is at x = +-0.25 (half length) with the rim 0.1 away: hypot(0.25, 0.1) from the axis.
  PlacedShape placed{Cylinder{0.1, 0.5}, Eigen::Isometry3d::Identity()};
  placed.pose.linear() = Eigen::AngleAxisd(M_PI / 2.0, Eigen::Vector3d::UnitY()).toRotationMatrix();
  placed.pose.translation() = Eigen::Vector3d(0.0, 0.0, 2.0);
  double farthest = 0.0;
  for (const auto& point : extreme_points(placed)) {
    farthest = std::max(farthest, std::hypot(point.x(), point.y()));
  }
  EXPECT_GE(farthest, std::hypot(0.25, 0.1) - 1e-12);
  EXPECT_LE(farthest, std::hypot(0.25, 0.1) * 1.01);
}

}  // namespace
}  // namespace safecell
