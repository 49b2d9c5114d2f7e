#include <gtest/gtest.h>

#include <random>
#include <stdexcept>
#include <vector>

#include "safecell/lut/box_cover.hpp"
#include "safecell/lut/pixel_to_cells_table.hpp"
#include "safecell/test/property.hpp"

namespace safecell {
namespace {

// A grid with the given number of joints of roughly `cells` cells each (one joint may be kept
// whole, as the wrist is).
CspaceGrid random_grid(std::mt19937_64& rng, std::uint32_t joints, double cells_scale) {
  GridSpec spec;
  spec.m_max_m = 0.1;
  spec.joint_count = joints;
  for (std::uint32_t j = 0; j < joints; ++j) {
    const double cells = std::uniform_real_distribution<double>(1.0, cells_scale)(rng);
    // dq = 2 asin(m / 2l): pick l so that a range of 1 rad holds about `cells` cells.
    spec.joints[j] = JointSpec{0.0, 1.0, 0.1 / (2.0 * std::sin(0.5 / cells)),
                               std::bernoulli_distribution(0.8)(rng)};
  }
  auto grid = CspaceGrid::create(spec);
  if (!grid.ok()) throw std::runtime_error("bad random grid");
  return grid.value();
}

CellSet random_cells(std::mt19937_64& rng, const CspaceGrid& grid) {
  CellSet cells(grid.cell_count());
  std::uniform_int_distribution<CellIndex> any(0, grid.cell_count() - 1);
  const int blobs = std::uniform_int_distribution<int>(0, 4)(rng);
  for (int b = 0; b < blobs; ++b) {
    // A blob: every cell within a random distance of a random centre (in cell steps).
    const GridCoords centre = grid.coords_of(any(rng)).value();
    const double radius = std::uniform_real_distribution<double>(0.5, 6.0)(rng);
    for (CellIndex c = 0; c < grid.cell_count(); ++c) {
      const GridCoords at = grid.coords_of(c).value();
      double d2 = 0.0;
      for (std::uint32_t j = 0; j < grid.joint_count(); ++j) {
        const double d = static_cast<double>(at.along[j]) - static_cast<double>(centre.along[j]);
        d2 += d * d;
      }
      if (d2 <= radius * radius) cells.set(c);
    }
  }
  for (int k = 0; k < 20; ++k) cells.set(any(rng));
  return cells;
}

CellSet decoded(const PixelToCellsTable& table) {
  CellSet cells(table.cell_count());
  table.for_each_cell(0, [&](CellIndex c) { cells.set(c); });
  return cells;
}

TEST(BoxCoding, BoxesDecodeToExactlyTheCells) {
  test::PropertyRun run(60);
  for (int i = 0; i < run.iterations(); ++i) {
    const auto joints = std::uniform_int_distribution<std::uint32_t>(1, 5)(run.rng());
    const CspaceGrid grid = random_grid(run.rng(), joints, 12.0);
    const CellSet cells = random_cells(run.rng(), grid);
    std::vector<std::uint8_t> bytes;
    const std::size_t boxes = append_boxes(cells, BoxAxes::of(grid), bytes);
    const PixelToCellsTable table(grid, 1, 1, {0, bytes.size()}, bytes);
    EXPECT_EQ(table.total_boxes(), boxes);
    EXPECT_EQ(decoded(table), cells) << grid.cell_count() << " cells";
    CellSet added(grid.cell_count());
    table.add_cells(0, added);
    EXPECT_EQ(added, cells);
    EXPECT_LE(boxes, cells.count());
  }
}

TEST(BoxCoding, LongRunsAreCutAt255Cells) {
  GridSpec spec;
  spec.m_max_m = 0.01;
  spec.joint_count = 2;
  spec.joints[0] = JointSpec{0.0, 3.0, 1.0, true};  // 300 cells
  spec.joints[1] = JointSpec{0.0, 1.0, 1.0, true};  // 100 cells
  const CspaceGrid grid = CspaceGrid::create(spec).value();
  ASSERT_GT(grid.cells_along(0), 255U);
  CellSet cells(grid.cell_count());
  cells.fill();
  std::vector<std::uint8_t> bytes;
  const std::size_t boxes = append_boxes(cells, BoxAxes::of(grid), bytes);
  EXPECT_EQ(boxes, 2U);  // 255 + 45 along joint 0, each 100 deep along joint 1
  const PixelToCellsTable table(grid, 1, 1, {0, bytes.size()}, bytes);
  EXPECT_EQ(decoded(table), cells);
}

TEST(BoxCoding, ASetIndependentOfTheTrailingJointsIsCutIntoBoxesSpanningThemWhole) {
  GridSpec spec;
  spec.m_max_m = 0.1;
  spec.joint_count = 3;
  spec.joints[0] = JointSpec{0.0, 1.0, 1.0, true};  // 10 cells
  spec.joints[1] = JointSpec{0.0, 1.0, 1.0, true};  // 10 cells
  spec.joints[2] = JointSpec{0.0, 0.6, 1.0, true};  // 6 cells
  const CspaceGrid grid = CspaceGrid::create(spec).value();
  const BoxAxes axes = BoxAxes::of(grid);
  // A disc over joints 0 and 1, the same at every joint-2 cell, plus one cell of its own.
  CellSet cells(grid.cell_count());
  for (CellIndex c = 0; c < grid.cell_count(); ++c) {
    const GridCoords at = grid.coords_of(c).value();
    const int dx = static_cast<int>(at.along[0]) - 4;
    const int dy = static_cast<int>(at.along[1]) - 5;
    if (dx * dx + dy * dy <= 9) cells.set(c);
  }
  cells.set(99 + 100 * 3);  // joint 0 and 1 at their last cell, joint 2 at 3
  std::vector<std::uint8_t> bytes;
  append_boxes(cells, axes, bytes);
  const PixelToCellsTable table(grid, 1, 1, {0, bytes.size()}, bytes);
  EXPECT_EQ(decoded(table), cells);
  std::size_t whole = 0;
  std::size_t single = 0;
  table.for_each_box(0, [&](CellIndex start, const std::uint8_t* extents) {
    if (extents[2] == 6) ++whole;
    if (start == 399 && extents[0] == 1 && extents[1] == 1 && extents[2] == 1) ++single;
  });
  EXPECT_EQ(whole + single, table.total_boxes()) << "every disc box spans joint 2 whole";
  EXPECT_EQ(single, 1U);
}

TEST(BoxCoding, MalformedTablesAreRefused) {
  GridSpec spec;
  spec.m_max_m = 0.1;
  spec.joint_count = 2;
  spec.joints[0] = JointSpec{0.0, 1.0, 1.0, true};
  spec.joints[1] = JointSpec{0.0, 1.0, 1.0, true};
  const CspaceGrid grid = CspaceGrid::create(spec).value();  // 10 x 10
  const auto table_of = [&grid](std::vector<std::uint8_t> bytes, std::uint64_t end) {
    return PixelToCellsTable(grid, 1, 1, {0, end}, std::move(bytes));
  };
  // A box: the lowest cell as a LEB128 difference, then the extents along joints 1 and 2.
  EXPECT_NO_THROW(table_of({0, 10, 10}, 3));
  EXPECT_NO_THROW(table_of({0, 1, 1, 0x0B, 9, 9}, 6));             // the second box from cell 11
  EXPECT_THROW(table_of({5, 6, 1}, 3), std::invalid_argument);     // runs past joint 1's end
  EXPECT_THROW(table_of({0, 0, 1}, 3), std::invalid_argument);     // an empty extent
  EXPECT_THROW(table_of({100, 1, 1}, 3), std::invalid_argument);   // starts outside the grid
  EXPECT_THROW(table_of({0x80, 1, 1}, 3), std::invalid_argument);  // cell number cut off
  EXPECT_THROW(table_of({0, 10}, 2), std::invalid_argument);       // extents cut off
  EXPECT_THROW(table_of({0, 10, 10}, 2), std::invalid_argument);   // offsets do not span
  EXPECT_THROW(PixelToCellsTable(grid, 2, 1, {0, 3}, std::vector<std::uint8_t>{0, 10, 10}),
               std::invalid_argument);  // two pixels, one offset pair
}

}  // namespace
}  // namespace safecell
