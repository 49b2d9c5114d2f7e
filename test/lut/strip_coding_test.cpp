#include <gtest/gtest.h>

#include <random>
#include <stdexcept>
#include <vector>

#include "safecell/tables/pixel_to_cells_table.hpp"
#include "safecell/tables/strip_cover.hpp"
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

CellSet filled_through_lines(const PixelToCellsTable& table) {
  CellLines lines(table.axes(), table.cell_count());
  table.add_cells(0, lines);
  CellSet cells(table.cell_count());
  lines.pack_into(cells);
  return cells;
}

TEST(StripCoding, StripsDecodeToExactlyTheCells) {
  test::PropertyRun run(60);
  for (int i = 0; i < run.iterations(); ++i) {
    const auto joints = std::uniform_int_distribution<std::uint32_t>(1, 5)(run.rng());
    const CspaceGrid grid = random_grid(run.rng(), joints, 12.0);
    const CellSet cells = random_cells(run.rng(), grid);
    std::vector<std::uint8_t> bytes;
    const std::size_t strips = append_strips(cells, BoxAxes::of(grid), bytes);
    const PixelToCellsTable table(grid, 1, 1, {0, bytes.size()}, bytes);
    EXPECT_EQ(table.total_strips(), strips);
    EXPECT_EQ(decoded(table), cells) << grid.cell_count() << " cells";
    CellSet added(grid.cell_count());
    table.add_cells(0, added);
    EXPECT_EQ(added, cells);
    EXPECT_EQ(filled_through_lines(table), cells);
  }
}

TEST(StripCoding, WithKnownCellsOnlyWhatTheyLackIsCodedAndNothingOutsideTheSet) {
  test::PropertyRun run(60);
  for (int i = 0; i < run.iterations(); ++i) {
    const auto joints = std::uniform_int_distribution<std::uint32_t>(1, 5)(run.rng());
    const CspaceGrid grid = random_grid(run.rng(), joints, 12.0);
    const CellSet cells = random_cells(run.rng(), grid);
    CellSet known = random_cells(run.rng(), grid);
    if (std::bernoulli_distribution(0.5)(run.rng())) known |= cells;  // nothing left to code
    std::vector<std::uint8_t> bytes;
    append_strips(cells, BoxAxes::of(grid), bytes, &known);
    const PixelToCellsTable table(grid, 1, 1, {0, bytes.size()}, bytes);
    const CellSet difference = decoded(table);
    CellSet outside = difference;
    for (std::size_t w = 0; w < outside.words().size(); ++w) {
      outside.words()[w] &= ~cells.words()[w];
    }
    EXPECT_FALSE(outside.any()) << "a run leaves the set";
    CellSet both = difference;
    both |= known;
    CellSet all = cells;
    all |= known;
    EXPECT_EQ(both, all) << "with the known cells the difference gives the whole set";
  }
}

TEST(StripCoding, LinesLongerThanAWordAndRunsFromCell128On) {
  GridSpec spec;
  spec.m_max_m = 0.01;
  spec.joint_count = 2;
  spec.joints[0] = JointSpec{0.0, 3.0, 1.0, true};  // 300 cells
  spec.joints[1] = JointSpec{0.0, 0.1, 1.0, true};  // 10 cells
  const CspaceGrid grid = CspaceGrid::create(spec).value();
  ASSERT_GT(grid.cells_along(0), 255U);
  CellSet cells(grid.cell_count());
  cells.set_range(0, 300);                // line 0 whole
  cells.set_range(300 + 130, 300 + 290);  // line 1: a run from cell 130 on
  cells.set_range(2700 + 63, 2700 + 65);  // line 9: across a word boundary
  std::vector<std::uint8_t> bytes;
  append_strips(cells, BoxAxes::of(grid), bytes);
  const PixelToCellsTable table(grid, 1, 1, {0, bytes.size()}, bytes);
  EXPECT_EQ(decoded(table), cells);
  EXPECT_EQ(filled_through_lines(table), cells);
}

TEST(StripCoding, ASetIndependentOfTheTrailingJointsIsStoredOnItsOwnLevel) {
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
  cells.set(99 + 100 * 3);  // joints 0 and 1 at their last cell, joint 2 at 3
  std::vector<std::uint8_t> bytes;
  append_strips(cells, axes, bytes);
  const PixelToCellsTable table(grid, 1, 1, {0, bytes.size()}, bytes);
  EXPECT_EQ(decoded(table), cells);
  const LineLevels& levels = table.levels();
  std::vector<std::size_t> lines;
  table.for_each_line_run(0, [&](std::size_t line, LineRun) { lines.push_back(line); });
  // The disc's 7 lines (joint 1 at 2..8) on level 2, the lone cell's line on level 3.
  ASSERT_EQ(lines.size(), 8U);
  for (std::size_t k = 0; k < 7; ++k) EXPECT_EQ(lines[k], levels.first_line[2] + 2 + k);
  EXPECT_EQ(lines[7], levels.first_line[3] + 9 + 10 * 3);
  CellLines filled(axes, grid.cell_count());
  EXPECT_EQ(table.add_cells(0, filled), 8U);
}

TEST(StripCoding, MalformedTablesAreRefused) {
  GridSpec spec;
  spec.m_max_m = 0.1;
  spec.joint_count = 2;
  spec.joints[0] = JointSpec{0.0, 1.0, 1.0, true};
  spec.joints[1] = JointSpec{0.0, 1.0, 1.0, true};
  const CspaceGrid grid = CspaceGrid::create(spec).value();  // 10 x 10: lines 0 (level 1), 1..10
  const auto table_of = [&grid](std::vector<std::uint8_t> bytes, std::uint64_t end) {
    return PixelToCellsTable(grid, 1, 1, {0, end}, std::move(bytes));
  };
  // A strip: its first line as a LEB128 difference, its line count, then per line the first
  // cell and the length of its run.
  EXPECT_NO_THROW(table_of({0, 1, 0, 10}, 4));                     // all cells: line 0 of level 1
  EXPECT_NO_THROW(table_of({1, 2, 0, 5, 3, 2}, 6));                // lines 1 and 2 of level 2
  EXPECT_NO_THROW(table_of({1, 1, 0, 1, 9, 1, 9, 1}, 8));          // a second strip from line 10
  EXPECT_THROW(table_of({1, 1, 8, 3}, 4), std::invalid_argument);  // runs past the line
  EXPECT_THROW(table_of({1, 1, 0, 0}, 4), std::invalid_argument);  // an empty run
  EXPECT_THROW(table_of({1, 0}, 2), std::invalid_argument);        // no lines
  EXPECT_THROW(table_of({10, 2, 0, 1, 0, 1}, 6), std::invalid_argument);    // lines past the last
  EXPECT_THROW(table_of({0x81, 0x00, 1, 0, 1}, 5), std::invalid_argument);  // 1 in two bytes
  EXPECT_THROW(table_of({1, 2, 0, 5}, 4), std::invalid_argument);           // second run cut off
  EXPECT_THROW(table_of({0x80}, 1), std::invalid_argument);                 // line number cut off
  EXPECT_THROW(table_of({1, 1, 0, 1}, 3), std::invalid_argument);           // offsets do not span
  EXPECT_THROW(PixelToCellsTable(grid, 2, 1, {0, 4}, std::vector<std::uint8_t>{0, 1, 0, 10}),
               std::invalid_argument);  // two pixels, one offset pair
}

}  // namespace
}  // namespace safecell
