#include "safecell/base/freestanding_math.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "safecell/test/property.hpp"

namespace safecell {
namespace {

TEST(FreestandingMath, AsinAtKnownPoints) {
  EXPECT_EQ(asin_rad(0.0), 0.0);
  EXPECT_DOUBLE_EQ(asin_rad(0.5), kPi / 6.0);
  EXPECT_DOUBLE_EQ(asin_rad(-0.5), -kPi / 6.0);
  EXPECT_DOUBLE_EQ(asin_rad(std::sqrt(0.5)), kPi / 4.0);
  EXPECT_EQ(asin_rad(1.0), kPi / 2.0);
  EXPECT_TRUE(std::isnan(asin_rad(1.0000001)));
  EXPECT_TRUE(std::isnan(asin_rad(std::numeric_limits<double>::quiet_NaN())));
}

TEST(FreestandingMath, AsinAgreesWithTheHostLibrary) {
  test::PropertyRun run(20000);
  std::uniform_real_distribution<double> x(-1.0, 1.0);
  for (int i = 0; i < run.iterations(); ++i) {
    const double value = x(run.rng());
    // Near +-1 asin is ill-conditioned (slope -> infinity); compare relative to that slope.
    const double tolerance =
        4e-16 / std::sqrt(1.0 - value * value) + 1e-15 * std::abs(std::asin(value));
    ASSERT_NEAR(asin_rad(value), std::asin(value), tolerance) << "x = " << value;
  }
}

TEST(FreestandingMath, SinAgreesWithTheHostLibrary) {
  for (double angle = -kPi / 2.0; angle <= kPi / 2.0; angle += 0.001) {
    ASSERT_NEAR(sin_small_rad(angle), std::sin(angle), 4e-16) << angle;
  }
}

TEST(FreestandingMath, CeilAndFiniteness) {
  EXPECT_EQ(ceil_to_u64(0.0), 0u);
  EXPECT_EQ(ceil_to_u64(3.0), 3u);
  EXPECT_EQ(ceil_to_u64(3.0000001), 4u);
  EXPECT_EQ(ceil_to_u64(0.2), 1u);
  EXPECT_TRUE(is_finite(1.0));
  EXPECT_FALSE(is_finite(std::numeric_limits<double>::infinity()));
  EXPECT_FALSE(is_finite(-std::numeric_limits<double>::infinity()));
  EXPECT_FALSE(is_finite(std::numeric_limits<double>::quiet_NaN()));
  EXPECT_TRUE(is_finite_non_negative(0.0));
  EXPECT_FALSE(is_finite_non_negative(-1e-300));
  EXPECT_EQ(infinity(), std::numeric_limits<double>::infinity());
}

}  // namespace
}  // namespace safecell

namespace safecell {
namespace {

TEST(FreestandingMath, SqrtAgreesWithTheHostLibrary) {
  test::PropertyRun run(2000);
  for (int i = 0; i < run.iterations(); ++i) {
    const double exponent = std::uniform_real_distribution<double>(-300.0, 300.0)(run.rng());
    const double x = std::pow(10.0, exponent);
    ASSERT_NEAR(sqrt_of(x), std::sqrt(x), std::sqrt(x) * 4e-16) << "x = " << x;
  }
  EXPECT_EQ(sqrt_of(0.0), 0.0);
  EXPECT_EQ(sqrt_of(4.0), 2.0);
  EXPECT_TRUE(std::isnan(sqrt_of(-1.0)));
  EXPECT_TRUE(std::isnan(sqrt_of(std::numeric_limits<double>::infinity())));
}

}  // namespace
}  // namespace safecell
