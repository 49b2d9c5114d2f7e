#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <random>
#include <sstream>

#include "safecell/envelope/static_obstacle_cells.hpp"
#include "safecell/test/property.hpp"

namespace safecell {
namespace {

// The distance from a point to a placed box, face axis by face axis in the cell frame (not
// through the inverse pose): the offset along each of the box's axes, clamped to its half size,
// gives the closest point of the box.
double distance_to_box(const Eigen::Vector3d& point, const PlacedShape& placed) {
  const Eigen::Vector3d half = std::get<Box>(placed.shape).size_m / 2.0;
  const Eigen::Vector3d origin = placed.pose.translation();
  Eigen::Vector3d closest = origin;
  for (int axis = 0; axis < 3; ++axis) {
    const Eigen::Vector3d direction = placed.pose.linear().col(axis);
    const double along = (point - origin).dot(direction);
    closest += std::clamp(along, -half(axis), half(axis)) * direction;
  }
  return (point - closest).norm();
}

// Balls far and near, and balls that just reach (or just miss) a corner of a turned box: there a
// quick rejection by the box's bounding sphere is tightest. A rejection that forgot the ball's
// radius, or took the box's half size for its half diagonal, turns away corner balls that reach.
TEST(BallReaches, AgreesWithTheDistanceToTheBoxNearItsCornersToo) {
  test::PropertyRun run(4000);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  int corner_hits = 0;
  for (int i = 0; i < run.iterations(); ++i) {
    std::mt19937_64& rng = run.rng();
    PlacedShape placed;
    const Eigen::Vector3d size(0.6 + unit(rng) * 0.05, 0.3 + unit(rng) * 0.2,
                               0.8 + unit(rng) * 0.3);
    placed.shape = Box{size};
    placed.pose = Eigen::Translation3d(unit(rng), unit(rng), unit(rng)) *
                  Eigen::Quaterniond(
                      Eigen::Vector4d(unit(rng), unit(rng), unit(rng), unit(rng)).normalized());
    Ball ball;
    const bool at_corner = i % 2 == 0;
    if (at_corner) {
      // Outward from a corner, beyond it by 1 cm to 0.5 m; the radius the distance, give or take.
      Eigen::Vector3d corner = size / 2.0;
      Eigen::Vector3d outward;
      for (int axis = 0; axis < 3; ++axis) {
        const double sign = unit(rng) < 0 ? -1.0 : 1.0;
        corner(axis) *= sign;
        outward(axis) = sign * (0.05 + std::abs(unit(rng)));
      }
      ball.centre_m =
          placed.pose * (corner + outward.normalized() * (0.01 + 0.49 * std::abs(unit(rng))));
      ball.radius_m = distance_to_box(ball.centre_m, placed) * (1.0 + 1e-3 * unit(rng));
    } else {
      ball.centre_m =
          placed.pose.translation() + 2.0 * Eigen::Vector3d(unit(rng), unit(rng), unit(rng));
      ball.radius_m = std::abs(unit(rng));
    }
    const double distance = distance_to_box(ball.centre_m, placed);
    const bool reaches = distance <= ball.radius_m;
    corner_hits += at_corner && reaches ? 1 : 0;
    std::ostringstream input;
    input << "box " << size.transpose() << " at " << placed.pose.translation().transpose()
          << ", ball " << ball.centre_m.transpose() << " r " << ball.radius_m << ", distance "
          << distance;
    ASSERT_EQ(ball_reaches(ball, placed), reaches) << input.str();
  }
  if (run.full_length()) {
    EXPECT_GT(corner_hits, run.iterations() / 8) << "too few corner balls reach the box";
  }
}

}  // namespace
}  // namespace safecell
