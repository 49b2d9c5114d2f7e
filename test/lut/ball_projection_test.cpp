#include "safecell/envelope/ball_projection.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <optional>
#include <vector>

#include "../camera/random_camera.hpp"
#include "safecell/test/property.hpp"

namespace safecell {
namespace {

// A random camera cut to a size that 8 x 8 px feature cells tile (grids wider than 64 cells
// exercise masks of several words per row).
PinholeCamera tiled_camera(std::mt19937_64& rng, bool distorted) {
  const PinholeCamera camera = test::random_camera(rng, distorted);
  CameraIntrinsics intrinsics = camera.intrinsics();
  intrinsics.width_px -= intrinsics.width_px % 8;
  intrinsics.height_px -= intrinsics.height_px % 8;
  return PinholeCamera(camera.name(), intrinsics, camera.cell_to_camera());
}

FeatureGrid grid_of(const PinholeCamera& camera) {
  const CameraIntrinsics& k = camera.intrinsics();
  return FeatureGrid::tiling(k.width_px, k.height_px, k.width_px / 8, k.height_px / 8);
}

void expect_points_inside(const PinholeCamera& camera, const Ball& ball, std::mt19937_64& rng) {
  const FeatureGrid grid = grid_of(camera);
  const BallProjection projection(camera, grid);
  const auto rect = projection.feature_rect(ball);
  std::normal_distribution<double> normal;
  for (int k = 0; k < 400; ++k) {
    Eigen::Vector3d direction(normal(rng), normal(rng), normal(rng));
    const double scale =
        k % 2 == 0 ? 1.0 : std::cbrt(std::uniform_real_distribution<double>()(rng));
    const Eigen::Vector3d point = ball.centre_m + ball.radius_m * scale * direction.normalized();
    const auto pixel = camera.project(point);
    if (!pixel || !camera.in_image(*pixel)) continue;
    const auto cell = grid.cell_of(*pixel);
    ASSERT_TRUE(cell.has_value());
    ASSERT_TRUE(rect.has_value()) << "a visible point of the ball, but no rectangle";
    EXPECT_GE(cell->column, rect->col0);
    EXPECT_LE(cell->column, rect->col1);
    EXPECT_GE(cell->row, rect->row0);
    EXPECT_LE(cell->row, rect->row1);
  }
}

TEST(BallProjection, RectangleHoldsEveryVisiblePointOfTheBall) {
  test::PropertyRun run(300);
  for (int i = 0; i < run.iterations(); ++i) {
    const PinholeCamera camera = tiled_camera(run.rng(), i % 2 == 1);
    const Ball ball{
        Eigen::Vector3d(test::uniform(run.rng(), -1.5, 1.5), test::uniform(run.rng(), -1.5, 1.5),
                        test::uniform(run.rng(), 0.0, 2.0)),
        test::uniform(run.rng(), 0.01, 0.6)};
    expect_points_inside(camera, ball, run.rng());
  }
}

TEST(BallProjection, TightWithoutDistortion) {
  // A ball straight ahead: its image is a circle of radius f tan(asin(r / d)).
  const PinholeCamera camera =
      PinholeCamera::look_at("c", {0, 0, 3}, {0, 0, 0}, {0, 1, 0}, std::numbers::pi / 2, 704, 576);
  const FeatureGrid grid;  // 64 x 64 cells of 11 x 9 px
  const BallProjection projection(camera, grid);
  const auto rect = projection.feature_rect(Ball{{0, 0, 0}, 0.5});
  ASSERT_TRUE(rect.has_value());
  const double radius_px = camera.intrinsics().fx_px * std::tan(std::asin(0.5 / 3.0));
  const double centre_u = camera.intrinsics().cx_px;
  EXPECT_EQ(rect->col0, static_cast<int>(std::floor((centre_u - radius_px + 0.5) / 11.0)));
  EXPECT_EQ(rect->col1, static_cast<int>(std::floor((centre_u + radius_px + 0.5) / 11.0)));
}

TEST(BallProjection, BallAtTheCameraCoversTheImageAndBallBehindItNothing) {
  const PinholeCamera camera =
      PinholeCamera::look_at("c", {0, 0, 3}, {0, 0, 0}, {0, 1, 0}, std::numbers::pi / 2, 704, 576);
  const BallProjection projection(camera, FeatureGrid{});
  const auto whole = projection.feature_rect(Ball{{0.1, 0, 3.0}, 0.2});
  ASSERT_TRUE(whole.has_value());
  EXPECT_EQ(*whole, (FeatureRect{0, 0, 63, 63}));
  EXPECT_FALSE(projection.feature_rect(Ball{{0, 0, 5.0}, 0.5}).has_value());
  EXPECT_FALSE(projection.feature_rect(Ball{{30, 0, 0}, 0.5}).has_value());  // far off to the side
}

TEST(BallProjection, ManyBallsAtOnceGiveEachBallsRectangle) {
  // Batches of every length around the projection's batch size, with balls at and behind the
  // camera mixed in: each lane must give what the ball alone gives.
  test::PropertyRun run(60);
  for (int i = 0; i < run.iterations(); ++i) {
    const PinholeCamera camera = tiled_camera(run.rng(), i % 2 == 1);
    const BallProjection projection(camera, grid_of(camera));
    const Eigen::Vector3d eye = camera.cell_to_camera().inverse().translation();
    std::vector<Ball> balls;
    const auto length = static_cast<std::size_t>(test::uniform(run.rng(), 0.0, 40.0));
    for (std::size_t k = 0; k < length; ++k) {
      const bool at_camera = test::uniform(run.rng(), 0.0, 1.0) < 0.15;
      const Eigen::Vector3d offset(test::uniform(run.rng(), -1.5, 1.5),
                                   test::uniform(run.rng(), -1.5, 1.5),
                                   test::uniform(run.rng(), -1.0, 2.0));
      balls.push_back(Ball{at_camera ? Eigen::Vector3d(eye + 0.1 * offset) : offset,
                           test::uniform(run.rng(), 0.01, 0.6)});
    }
    std::vector<std::optional<FeatureRect>> rects(balls.size());
    projection.feature_rects(balls, rects);
    for (std::size_t k = 0; k < balls.size(); ++k) {
      EXPECT_EQ(rects[k], projection.feature_rect(balls[k])) << "ball " << k << " of " << length;
    }
  }
  const PinholeCamera camera =
      PinholeCamera::look_at("c", {0, 0, 3}, {0, 0, 0}, {0, 1, 0}, std::numbers::pi / 2, 704, 576);
  const BallProjection projection(camera, FeatureGrid{});
  const std::vector<Ball> two(2);
  std::vector<std::optional<FeatureRect>> one(1);
  EXPECT_THROW(projection.feature_rects(two, one), std::invalid_argument);
}

TEST(BallProjection, GridMustTileTheCamera) {
  const PinholeCamera camera =
      PinholeCamera::look_at("c", {0, 0, 3}, {0, 0, 0}, {0, 1, 0}, std::numbers::pi / 2, 640, 480);
  EXPECT_THROW(BallProjection(camera, FeatureGrid{}), std::invalid_argument);
}

}  // namespace
}  // namespace safecell
