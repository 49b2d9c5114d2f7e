#include "safecell/envelope/ball_groups.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <limits>
#include <sstream>
#include <string>
#include <tuple>
#include <vector>

#include "../camera/random_camera.hpp"
#include "safecell/test/property.hpp"

namespace safecell {
namespace {

// A robot-like chain of balls: a random walk of steps of about one radius, the radii of a table
// build's swept balls (4 cm and more).
std::vector<Ball> random_chain(std::mt19937_64& rng, std::size_t count) {
  std::vector<Ball> balls;
  Eigen::Vector3d at(test::uniform(rng, -1.0, 1.0), test::uniform(rng, -1.0, 1.0),
                     test::uniform(rng, 0.2, 1.8));
  for (std::size_t i = 0; i < count; ++i) {
    const double radius_m = test::uniform(rng, 0.04, 0.15);
    at += Eigen::Vector3d(test::uniform(rng, -1.0, 1.0), test::uniform(rng, -1.0, 1.0),
                          test::uniform(rng, -1.0, 1.0)) *
          radius_m;
    balls.push_back({at, radius_m});
  }
  return balls;
}

std::string describe(const std::vector<Ball>& balls) {
  std::ostringstream out;
  out.precision(17);
  for (const Ball& ball : balls) {
    out << "{" << ball.centre_m.x() << ", " << ball.centre_m.y() << ", " << ball.centre_m.z()
        << "; " << ball.radius_m << "} ";
  }
  return out.str();
}

bool same_set(std::vector<Ball> a, std::vector<Ball> b) {
  const auto before = [](const Ball& x, const Ball& y) {
    return std::tie(x.centre_m.x(), x.centre_m.y(), x.centre_m.z(), x.radius_m) <
           std::tie(y.centre_m.x(), y.centre_m.y(), y.centre_m.z(), y.radius_m);
  };
  std::sort(a.begin(), a.end(), before);
  std::sort(b.begin(), b.end(), before);
  return std::equal(a.begin(), a.end(), b.begin(), b.end(), [](const Ball& x, const Ball& y) {
    return x.centre_m == y.centre_m && x.radius_m == y.radius_m;
  });
}

TEST(BallGroups, GroupsCutTheBallsIntoRunsWhoseBoundsHoldThem) {
  test::PropertyRun run(500);
  for (int i = 0; i < run.iterations(); ++i) {
    const std::vector<Ball> input = random_chain(run.rng(), 1 + run.rng()() % 60);
    const std::size_t group_size = 1 + run.rng()() % 12;
    std::vector<Ball> balls = input;
    std::vector<BallGroup> groups;
    group_balls(balls, group_size, groups);
    ASSERT_TRUE(same_set(input, balls)) << "grouping changed the balls of " << describe(input);
    std::uint32_t next = 0;
    for (const BallGroup& group : groups) {
      ASSERT_EQ(group.first, next) << describe(input);
      ASSERT_GT(group.end, group.first) << describe(input);
      ASSERT_LE(group.end - group.first, group_size) << describe(input);
      for (std::uint32_t k = group.first; k < group.end; ++k) {
        EXPECT_LE((balls[k].centre_m - group.bound.centre_m).norm() + balls[k].radius_m,
                  group.bound.radius_m - 0.5 * BallGroup::kBoundMargin_m)
            << "ball " << k << " leaves its group's bound; groups of " << group_size << " of "
            << describe(input);
      }
      next = group.end;
    }
    ASSERT_EQ(next, balls.size()) << describe(input);
  }
  std::vector<Ball> balls;
  std::vector<BallGroup> groups;
  EXPECT_THROW(group_balls(balls, 0, groups), std::invalid_argument);
}

// The mask of the balls' "previous sub-cell": the same chain moved a little, grown by a feature
// cell, so that most groups find their rectangles set and the drawing skips them.
FeatureMask earlier_drawing(const BallProjection& projection, const FeatureGrid& grid,
                            std::vector<Ball> balls, std::mt19937_64& rng) {
  const Eigen::Vector3d shift(test::uniform(rng, -0.05, 0.05), test::uniform(rng, -0.05, 0.05),
                              test::uniform(rng, -0.05, 0.05));
  for (Ball& ball : balls) ball.centre_m += shift;
  FeatureMask mask(grid);
  add_ball_rects(projection, balls, mask);
  mask.dilate(1, 1);
  return mask;
}

// The groups' bounds as a broken grouping would make them: holding the balls' centres only.
std::vector<BallGroup> centres_only(const std::vector<Ball>& balls, std::vector<BallGroup> groups) {
  for (BallGroup& group : groups) {
    group.bound.radius_m = 0.0;
    for (std::uint32_t k = group.first; k < group.end; ++k) {
      group.bound.radius_m =
          std::max(group.bound.radius_m, (balls[k].centre_m - group.bound.centre_m).norm());
    }
  }
  return groups;
}

TEST(BallGroups, DrawingByGroupsGivesTheMaskOfEveryBall) {
  test::PropertyRun run(300);
  int skipping_runs = 0;
  int control_caught = 0;  // runs where bounds that leave the balls' radii out change the mask
  for (int i = 0; i < run.iterations(); ++i) {
    const bool distorted = i % 4 == 3;
    const PinholeCamera camera = test::random_camera(run.rng(), distorted);
    const CameraIntrinsics& k = camera.intrinsics();
    const FeatureGrid grid =
        FeatureGrid::tiling(k.width_px - k.width_px % 8, k.height_px - k.height_px % 8,
                            (k.width_px - k.width_px % 8) / 8, (k.height_px - k.height_px % 8) / 8);
    CameraIntrinsics tiled = k;
    tiled.width_px = grid.image_width_px();
    tiled.height_px = grid.image_height_px();
    const BallProjection projection(PinholeCamera(camera.name(), tiled, camera.cell_to_camera()),
                                    grid);
    std::vector<Ball> balls = random_chain(run.rng(), 40 + run.rng()() % 160);
    const std::string input = describe(balls);
    std::vector<BallGroup> groups;
    group_balls(balls, 1 + run.rng()() % 12, groups);
    const FeatureMask start = earlier_drawing(projection, grid, balls, run.rng());

    FeatureMask every_ball = start;
    add_ball_rects(projection, balls, every_ball);
    FeatureMask grouped = start;
    add_grouped_ball_rects(projection, balls, groups, grouped);
    ASSERT_TRUE(grouped == every_ball)
        << (distorted ? "distorted camera; " : "") << "balls " << input;
    if (!projection.rectangles_nest()) continue;

    // The runs must reach the skip: groups whose bound's rectangle the start mask holds, while
    // the balls still add cells elsewhere.
    const bool adds_cells = !(every_ball == start);
    for (const BallGroup& group : groups) {
      const auto rect = projection.feature_rect(group.bound);
      if (adds_cells && rect && start.all_in_rect(*rect)) {
        ++skipping_runs;
        break;
      }
    }
    // The negative control.
    FeatureMask broken = start;
    add_grouped_ball_rects(projection, balls, centres_only(balls, groups), broken);
    if (!(broken == every_ball)) ++control_caught;
  }
  if (run.full_length()) {
    EXPECT_GT(skipping_runs, run.iterations() / 8) << "too few runs skip a group";
    EXPECT_GT(control_caught, 0) << "bounds that hold only the balls' centres went unnoticed";
  }
}

// Balls the projection draws as the whole image or not at all: one that is not finite, one around
// the camera (across its near plane) and one behind it. Grouped with ordinary balls, each group
// must draw what drawing every ball does, from an empty mask and from one with cells set.
TEST(BallGroups, BallsNotFiniteAtOrBehindTheCameraAreDrawnAsEveryBallIs) {
  const PinholeCamera camera =
      PinholeCamera::look_at("c", {0, 0, 3}, {0, 0, 0}, {0, 1, 0}, 1.2, 704, 576);
  const FeatureGrid grid;  // 64 x 64 cells of 11 x 9 px
  const BallProjection projection(camera, grid);
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const std::vector<Ball> odd_balls = {
      {{nan, 0.0, 0.0}, 0.05},
      {{0.1, 0.0, 0.0}, std::numeric_limits<double>::infinity()},
      {{0.0, 0.0, 3.0}, 0.05},  // around the camera
      {{0.0, 0.0, 4.0}, 0.05},  // behind it
  };
  for (const Ball& odd : odd_balls) {
    const std::vector<Ball> ordinary_balls = {{{0.2, 0.1, 0.5}, 0.05}, {{0.25, 0.1, 0.5}, 0.05}};
    std::vector<Ball> balls = {ordinary_balls[0], odd, ordinary_balls[1]};
    std::vector<BallGroup> groups;
    group_balls(balls, 3, groups);
    // The ordinary balls drawn already, grown by two cells: their group's bound would be skipped
    // were the odd ball left out of it.
    FeatureMask ordinary(grid);
    add_ball_rects(projection, ordinary_balls, ordinary);
    ordinary.dilate(2, 2);
    for (const FeatureMask& start : {FeatureMask(grid), ordinary}) {
      FeatureMask every_ball = start;
      add_ball_rects(projection, balls, every_ball);
      FeatureMask grouped = start;
      add_grouped_ball_rects(projection, balls, groups, grouped);
      EXPECT_TRUE(grouped == every_ball) << describe({odd});
    }
  }
}

TEST(BallGroups, GroupsThatDoNotCutTheBallsIntoRunsAreRefused) {
  const PinholeCamera camera =
      PinholeCamera::look_at("c", {0, 0, 3}, {0, 0, 0}, {0, 1, 0}, 1.2, 704, 576);
  const FeatureGrid grid;
  const BallProjection projection(camera, grid);
  std::vector<Ball> balls = {
      {{0.0, 0.0, 0.5}, 0.05}, {{0.1, 0.0, 0.5}, 0.05}, {{0.2, 0.0, 0.5}, 0.05}};
  std::vector<BallGroup> groups;
  group_balls(balls, 2, groups);
  ASSERT_EQ(groups.size(), 2U);
  FeatureMask mask(grid);
  EXPECT_NO_THROW(add_grouped_ball_rects(projection, balls, groups, mask));
  const std::vector<BallGroup> short_of_one = {groups[0]};  // the last ball left out
  const std::vector<BallGroup> gap = {groups[0], {groups[1].bound, 3, 3}};  // ball 2 left out
  std::vector<BallGroup> past = groups;
  past.back().end = 4;  // a ball that is not there
  for (const auto& bad : {short_of_one, gap, past}) {
    EXPECT_THROW(add_grouped_ball_rects(projection, balls, bad, mask), std::invalid_argument);
  }
}

}  // namespace
}  // namespace safecell
