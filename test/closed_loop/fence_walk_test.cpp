// Walking along the fence: the shorter way round with every corner passed, points off the
// rectangle refused, and doorways kept on the rectangle even where an entry reaches a corner.

#include "safecell/closed_loop/fence_walk.hpp"

#include <gtest/gtest.h>

#include <stdexcept>

#include "safecell/cell/cell_file.hpp"

namespace safecell {
namespace {

const CellModel& default_model() {
  static const CellModel model = load_cell_model(load_cell_file_or_default(""));
  return model;
}

double length_m(const Eigen::Vector2d& from, const std::vector<Eigen::Vector2d>& path) {
  double length = (path.front() - from).norm();
  for (std::size_t i = 1; i < path.size(); ++i) length += (path[i] - path[i - 1]).norm();
  return length;
}

TEST(FenceWalk, TheShorterWayRoundThroughEveryCornerPassed) {
  const InsetRectangle fence(default_model());  // 4 m x 4 m: +-1.7 m
  ASSERT_DOUBLE_EQ(fence.hx, 1.7);
  const Eigen::Vector2d door(-1.7, -0.7);
  const auto there = fence.walk(door, {1.7, -1.0});
  ASSERT_EQ(there.size(), 3U);
  EXPECT_TRUE(there[0].isApprox(Eigen::Vector2d(-1.7, -1.7)));
  EXPECT_TRUE(there[1].isApprox(Eigen::Vector2d(1.7, -1.7)));
  EXPECT_NEAR(length_m(door, there), 1.0 + 3.4 + 0.7, 1e-9);
  // The other way round is shorter to a point on the +y side.
  const auto up = fence.walk(door, {0.0, 1.7});
  ASSERT_EQ(up.size(), 2U);
  EXPECT_TRUE(up[0].isApprox(Eigen::Vector2d(-1.7, 1.7)));
  // Along one side, and to itself: no corner.
  EXPECT_EQ(fence.walk(door, {-1.7, 0.5}).size(), 1U);
  EXPECT_EQ(fence.walk(door, door).size(), 1U);
  // From a corner.
  const auto from_corner = fence.walk({1.7, 1.7}, {-1.7, 1.0});
  ASSERT_EQ(from_corner.size(), 2U);
  EXPECT_TRUE(from_corner[0].isApprox(Eigen::Vector2d(-1.7, 1.7)));
  // Every point of the perimeter round trips.
  for (int step = 0; 0.37 * step < fence.perimeter(); ++step) {
    const double along = 0.37 * step;
    EXPECT_NEAR(fence.along(fence.point(along)), along, 1e-9) << along;
  }
}

TEST(FenceWalk, APointOffTheRectangleIsRefused) {
  const InsetRectangle fence(default_model());
  EXPECT_THROW(static_cast<void>(fence.along({0.0, 0.0})), std::logic_error);
  EXPECT_THROW(static_cast<void>(fence.along({-1.7, 1.9})), std::logic_error);
  EXPECT_THROW(static_cast<void>(fence.walk({-2.0, 0.0}, {1.7, 0.0})), std::logic_error);
}

TEST(FenceWalk, DoorwaysStayOnTheRectangleEvenAtACorner) {
  const CellModel& cell = default_model();
  const Doorway door = fence_doorway(cell, cell.config.entries->front(), 0.5);
  EXPECT_TRUE(door.inside_m.isApprox(Eigen::Vector2d(-1.7, -0.7)));
  EXPECT_TRUE(door.outside_m.isApprox(Eigen::Vector2d(-2.6, -0.7)));
  const EntryConfig corner_gate{"gate", CellWall::kPlusY, {1.8, 2.0}, {}};
  const Doorway gate = fence_doorway(cell, corner_gate, 1.0);
  EXPECT_TRUE(gate.inside_m.isApprox(Eigen::Vector2d(1.7, 1.7)));
  EXPECT_TRUE(gate.outside_m.isApprox(Eigen::Vector2d(1.7, 2.6)));
  EXPECT_NO_THROW(static_cast<void>(InsetRectangle(cell).along(gate.inside_m)));
}

}  // namespace
}  // namespace safecell
