#include "safecell/camera/lens_distortion.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "random_camera.hpp"
#include "safecell/test/property.hpp"

namespace safecell {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

TEST(LensDistortion, DistortsByHand) {
  const LensDistortion lens{0.1, 0.01, 0.002, -0.003, 0.001};
  // x = 0.3, y = -0.2: r^2 = 0.13, radial = 1 + 0.013 + 0.000169 + 0.000002197 = 1.013171197;
  // x_d = 0.3 radial + 2 p1 x y + p2 (r^2 + 2 x^2) = 0.3039513591 - 0.00024 - 0.00093
  // y_d = -0.2 radial + p1 (r^2 + 2 y^2) + 2 p2 x y = -0.2026342394 + 0.00042 + 0.00036
  const Eigen::Vector2d distorted = distort(lens, {0.3, -0.2});
  EXPECT_NEAR(distorted.x(), 0.3027813591, 1e-12);
  EXPECT_NEAR(distorted.y(), -0.2018542394, 1e-12);
  // No distortion is the identity.
  EXPECT_EQ(distort(LensDistortion{}, {0.3, -0.2}), Eigen::Vector2d(0.3, -0.2));
}

TEST(LensDistortion, MonotonicRadiusByHand) {
  // 1 + 3 k1 s = 0 -> s = 1 / 0.6.
  EXPECT_NEAR(monotonic_radius_sq({-0.2, 0, 0, 0, 0}), 1.0 / 0.6, 1e-12);
  // 1 + 5 k2 s^2 = 0 -> s = sqrt(1 / 0.5).
  EXPECT_NEAR(monotonic_radius_sq({0, -0.1, 0, 0, 0}), std::sqrt(2.0), 1e-12);
  // 1 + 7 k3 s^3 = 0 -> s = cbrt(1 / 0.07).
  EXPECT_NEAR(monotonic_radius_sq({0, 0, 0, 0, -0.01}), std::cbrt(1.0 / 0.07), 1e-12);
  EXPECT_EQ(monotonic_radius_sq(LensDistortion{}), kInf);
  EXPECT_EQ(monotonic_radius_sq({0.1, 0.01, 0.001, 0.001, 0.001}), kInf);
  // A positive k2 can hold barrel distortion back: 1 - 0.9 s + 0.25 s^2 > 0 for all s ...
  EXPECT_EQ(monotonic_radius_sq({-0.3, 0.05, 0, 0, 0}), kInf);
  // ... and 1 - 1.5 s + 0.5 s^2 = (1 - s)(1 - 0.5 s) folds at s = 1.
  EXPECT_NEAR(monotonic_radius_sq({-0.5, 0.1, 0, 0, 0}), 1.0, 1e-12);
}

TEST(LensDistortion, UndistortInvertsDistort) {
  test::PropertyRun run(2000);
  for (int i = 0; i < run.iterations(); ++i) {
    const LensDistortion lens{
        test::uniform(run.rng(), -0.3, 0.3), test::uniform(run.rng(), -0.05, 0.05),
        test::uniform(run.rng(), -5e-3, 5e-3), test::uniform(run.rng(), -5e-3, 5e-3),
        test::uniform(run.rng(), -0.01, 0.01)};
    const double max_radius_sq = monotonic_radius_sq(lens);
    const double radius = std::sqrt(std::min(max_radius_sq, 1.5)) * 0.95;
    const double angle = test::uniform(run.rng(), 0.0, 2.0 * std::numbers::pi);
    const double r = radius * std::sqrt(test::uniform(run.rng(), 0.0, 1.0));
    const Eigen::Vector2d point(r * std::cos(angle), r * std::sin(angle));
    const auto back = undistort(lens, distort(lens, point), max_radius_sq);
    ASSERT_TRUE(back.has_value()) << "iteration " << i << " point " << point.transpose();
    EXPECT_LT((*back - point).norm(), 1e-13) << "iteration " << i;
  }
}

TEST(LensDistortion, UndistortRefusesWhatNoPointMapsTo) {
  const LensDistortion barrel{-0.2, 0, 0, 0, 0};
  const double max_radius_sq = monotonic_radius_sq(barrel);
  // The radial mapping r (1 - 0.2 r^2) peaks at r = sqrt(1 / 0.6), at 0.8607; beyond, nothing.
  const double peak = std::sqrt(1.0 / 0.6) * (1.0 - 0.2 / 0.6);
  EXPECT_TRUE(undistort(barrel, {0.99 * peak, 0.0}, max_radius_sq).has_value());
  EXPECT_FALSE(undistort(barrel, {1.01 * peak, 0.0}, max_radius_sq).has_value());
  EXPECT_FALSE(undistort(barrel, {std::nan(""), 0.0}, max_radius_sq).has_value());
  EXPECT_FALSE(undistort(LensDistortion{}, {kInf, 0.0}, kInf).has_value());
}

}  // namespace
}  // namespace safecell
