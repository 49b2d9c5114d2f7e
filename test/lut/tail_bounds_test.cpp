#include <gtest/gtest.h>

#include <vector>

#include "model_fixture.hpp"
#include "safecell/envelope/cell_envelope.hpp"
#include "safecell/envelope/robot_balls.hpp"
#include "safecell/robot/robot_parts.hpp"

namespace safecell {
namespace {

// Every ball of every cell's tail lies inside one of the cell's tail bounds: a test against the
// bounds that fails for a cell fails for all its balls. The head as small as it goes (the tail
// from link 1: placed per cell, no sweep), then one and two bodies more (swept per cell by joint
// 1, by joints 2 and 1).
TEST(TailBounds, HoldEveryBallOfTheTail) {
  const CellModel cell = test::coarse_default_cell();
  const CspaceGrid grid = make_grid(cell.config);
  std::vector<std::size_t> part_starts;
  for (const RobotPart& part : robot_parts(*cell.robot, cell.robot_parts)) {
    part_starts.push_back(part.first_body);
  }
  const std::size_t along_1 = grid.cells_along(0);
  const std::size_t along_2 = grid.cells_along(1);
  for (const std::size_t head_prefixes : {std::size_t{1}, along_1, along_1 * along_2}) {
    const CellEnvelope envelope(*cell.robot, cover_with_balls(*cell.robot, cell.ball_radius_m),
                                grid, 0.02, part_starts, head_prefixes);
    std::vector<Ball> balls;
    std::vector<Ball> bounds;
    std::size_t bounded_cells = 0;
    for (CellIndex index = 0; index < grid.cell_count(); ++index) {
      const GridCoords coords = grid.coords_of(index).value();
      if (!envelope.tail_bounds(coords, bounds)) continue;
      ++bounded_cells;
      envelope.balls_of_bodies(coords, envelope.tail_body(), envelope.body_count(), balls);
      ASSERT_FALSE(balls.empty());
      for (const Ball& ball : balls) {
        bool inside = false;
        for (const Ball& bound : bounds) {
          inside =
              inside || (ball.centre_m - bound.centre_m).norm() + ball.radius_m <= bound.radius_m;
        }
        ASSERT_TRUE(inside) << "head of " << head_prefixes << " prefixes, tail from body "
                            << envelope.tail_body() << ", cell " << index << ": the ball at "
                            << ball.centre_m.transpose() << " r " << ball.radius_m;
      }
    }
    EXPECT_EQ(envelope.tail_body(), head_prefixes == 1 ? 1U : head_prefixes == along_1 ? 2U : 3U);
    EXPECT_EQ(bounded_cells, grid.cell_count())
        << "head of " << head_prefixes << " prefixes: cells of at most 120 degrees have bounds";
  }
}

}  // namespace
}  // namespace safecell
