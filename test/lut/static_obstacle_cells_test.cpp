#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "model_fixture.hpp"
#include "safecell/envelope/cell_envelope.hpp"
#include "safecell/envelope/robot_balls.hpp"
#include "safecell/envelope/static_obstacle_cells.hpp"
#include "safecell/test/property.hpp"

namespace safecell {
namespace {

// The coarse cell's envelope with its head as small as it goes (the tail, made per line of joint-0
// cells and moved along it, from link 1): on the coarse grid the default head would hold the whole
// robot, and the lines would not be tested.
CellEnvelope coarse_envelope(const CellModel& cell, const CspaceGrid& grid) {
  CellEnvelope envelope(*cell.robot, cover_with_balls(*cell.robot, 0.06), grid, 0.02, {}, 1);
  EXPECT_EQ(envelope.tail_body(), 1U);
  return envelope;
}

// How far the balls of bodies 1.. of `cell`, computed directly, are from those of its line's
// first cell moved by `motion`: the largest distance of a centre or difference of a radius (m);
// infinite when the counts differ.
double moved_balls_error(const CellEnvelope& envelope, GridCoords coords,
                         const Eigen::Isometry3d& motion) {
  std::vector<Ball> direct;
  std::vector<Ball> first;
  envelope.balls_of_bodies(coords, 1, envelope.body_count(), direct);
  coords.along[0] = 0;
  envelope.balls_of_bodies(coords, 1, envelope.body_count(), first);
  if (direct.size() != first.size()) return std::numeric_limits<double>::infinity();
  double error = 0.0;
  for (std::size_t i = 0; i < direct.size(); ++i) {
    error = std::max({error, (motion * first[i].centre_m - direct[i].centre_m).norm(),
                      std::abs(first[i].radius_m - direct[i].radius_m)});
  }
  return error;
}

// Every cell's balls (but the base's) are its line's first cell's moved by the joint-0 motion of
// its cell, to rounding. Control: the motions the other way round (a turn of the wrong sign) are
// off by metres.
TEST(FirstJointMotions, CarryTheFirstCellOfALineOntoEveryOther) {
  const CellModel cell = test::coarse_default_cell();
  const CspaceGrid grid = make_grid(cell.config);
  const CellEnvelope envelope = coarse_envelope(cell, grid);
  std::vector<Eigen::Isometry3d> motions;
  envelope.first_joint_motions(motions);
  ASSERT_EQ(motions.size(), grid.cells_along(0));
  double worst = 0.0;
  double worst_inverted = 0.0;
  for (CellIndex index = 0; index < grid.cell_count(); ++index) {
    const GridCoords coords = grid.coords_of(index).value();
    const Eigen::Isometry3d& motion = motions[coords.along[0]];
    const double error = moved_balls_error(envelope, coords, motion);
    ASSERT_LE(error, 1e-12) << "cell " << index << " (joint-0 cell " << coords.along[0] << ")";
    worst = std::max(worst, error);
    worst_inverted =
        std::max(worst_inverted, moved_balls_error(envelope, coords, motion.inverse()));
  }
  RecordProperty("worst_error_m", std::to_string(worst));
  EXPECT_GT(worst_inverted, 0.5) << "control: turning the other way must be caught";
}

// A random box (or sphere, cylinder) somewhere the arm can reach, turned about a random axis.
PlacedShape random_obstacle(std::mt19937_64& rng) {
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  std::uniform_real_distribution<double> size(0.05, 0.8);
  PlacedShape placed;
  switch (rng() % 3) {
    case 0:
      placed.shape = Box{Eigen::Vector3d(size(rng), size(rng), size(rng))};
      break;
    case 1:
      placed.shape = Sphere{size(rng) / 2.0};
      break;
    default:
      placed.shape = Cylinder{size(rng) / 2.0, size(rng)};
  }
  placed.pose =
      Eigen::Translation3d(2.0 * unit(rng), 2.0 * unit(rng), 1.0 + unit(rng)) *
      Eigen::Quaterniond(Eigen::Vector4d(unit(rng), unit(rng), unit(rng), unit(rng)).normalized());
  return placed;
}

// The cells whose envelope (every ball, computed directly per cell) reaches an obstacle.
CellSet direct_static_cells(const CellEnvelope& envelope,
                            const std::vector<PlacedShape>& obstacles) {
  const CspaceGrid& grid = envelope.grid();
  CellSet cells(grid.cell_count());
  std::vector<Ball> balls;
  for (CellIndex index = 0; index < grid.cell_count(); ++index) {
    envelope.balls_of_cell(grid.coords_of(index).value(), balls);
    for (const Ball& ball : balls) {
      for (const PlacedShape& obstacle : obstacles) {
        if (ball_reaches(ball, obstacle)) cells.set(index);
      }
    }
  }
  return cells;
}

std::string describe(const std::vector<PlacedShape>& obstacles) {
  std::ostringstream text;
  for (const PlacedShape& obstacle : obstacles) {
    text << "shape " << obstacle.shape.index() << " at " << obstacle.pose.translation().transpose()
         << " turned " << Eigen::Quaterniond(obstacle.pose.linear()).coeffs().transpose() << "; ";
  }
  return text.str();
}

// The static cells (bounds per line, balls moved along it) are exactly the cells whose envelope,
// computed directly cell by cell, reaches an obstacle. Control: the obstacles 2 cm off their
// place must give other cells in most runs, or random obstacles would hide an error of that size.
TEST(StaticObstacleCells, AreTheCellsWhoseEnvelopeReachesAnObstacle) {
  test::PropertyRun run(12);
  const CellModel cell = test::coarse_default_cell();
  const CspaceGrid grid = make_grid(cell.config);
  const CellEnvelope envelope = coarse_envelope(cell, grid);
  int partly_hit_runs = 0;
  int control_caught = 0;
  for (int i = 0; i < run.iterations(); ++i) {
    std::vector<PlacedShape> obstacles;
    for (int count = 1 + static_cast<int>(run.rng()() % 2); count > 0; --count) {
      obstacles.push_back(random_obstacle(run.rng()));
    }
    const CellSet expected = direct_static_cells(envelope, obstacles);
    const CellSet cells = static_obstacle_cells(envelope, obstacles, 2);
    if (cells != expected) {
      CellIndex differing = 0;
      while (cells.test(differing) == expected.test(differing)) ++differing;
      FAIL() << "run " << i << ", obstacles " << describe(obstacles) << "cell " << differing
             << ": static " << cells.test(differing) << ", direct " << expected.test(differing);
    }
    const bool partly_hit = expected.count() > 0 && expected.count() < grid.cell_count();
    partly_hit_runs += partly_hit ? 1 : 0;
    std::vector<PlacedShape> moved = obstacles;
    for (PlacedShape& obstacle : moved) obstacle.pose.pretranslate(Eigen::Vector3d(0.02, 0, 0));
    control_caught += partly_hit && static_obstacle_cells(envelope, moved, 2) != expected ? 1 : 0;
  }
  if (run.full_length()) {
    EXPECT_GT(partly_hit_runs, run.iterations() / 2) << "too few obstacles reach some cells";
    EXPECT_GT(control_caught, partly_hit_runs / 2) << "control: 2 cm off must be caught";
  }
}

}  // namespace
}  // namespace safecell
