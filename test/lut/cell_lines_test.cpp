#include "safecell/cellsets/cell_lines.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <span>
#include <stdexcept>
#include <string>
#include <vector>

#include "safecell/cellsets/cell_slices.hpp"
#include "safecell/tables/pixel_to_cells_table.hpp"
#include "safecell/tables/strip_cover.hpp"
#include "safecell/test/property.hpp"

namespace safecell {
namespace {

// Box axes of a grid with `count` axes of random sizes; joint 0 up to 150 cells, so that lines of
// one word and of several words are both drawn.
BoxAxes random_axes(std::mt19937_64& rng) {
  BoxAxes axes;
  axes.count = std::uniform_int_distribution<std::uint32_t>(1, 6)(rng);
  CellIndex stride = 1;
  for (std::uint32_t axis = 0; axis < axes.count; ++axis) {
    axes.joint[axis] = axis;
    axes.stride[axis] = stride;
    axes.cells[axis] = std::uniform_int_distribution<std::uint32_t>(
        2, axis == 0 ? 150 : (axes.count > 4 ? 4 : 9))(rng);
    stride *= axes.cells[axis];
  }
  return axes;
}

CellIndex cell_count_of(const BoxAxes& axes) {
  return axes.stride[axes.count - 1] * axes.cells[axes.count - 1];
}

// Random runs of cells in random lines of the grid.
CellSet random_runs(std::mt19937_64& rng, CellIndex cells, std::uint32_t line_cells) {
  CellSet set(cells);
  const int runs = std::uniform_int_distribution<int>(0, 12)(rng);
  for (int r = 0; r < runs; ++r) {
    const CellIndex line = std::uniform_int_distribution<CellIndex>(0, cells / line_cells - 1)(rng);
    const auto first = std::uniform_int_distribution<std::uint32_t>(0, line_cells - 1)(rng);
    const auto length = std::uniform_int_distribution<std::uint32_t>(1, line_cells - first)(rng);
    set.set_range(line * line_cells + first, line * line_cells + first + length);
  }
  return set;
}

void add(CellLines& lines, const CellSet& cells, const BoxAxes& axes) {
  std::vector<std::uint8_t> bytes;
  append_strips(cells, axes, bytes);
  lines.add_strips(bytes.data(), bytes.data() + bytes.size());
}

TEST(CellLines, PackedStripsEqualTheirCells) {
  test::PropertyRun run(300);
  for (int i = 0; i < run.iterations(); ++i) {
    const BoxAxes axes = random_axes(run.rng());
    const CellIndex cells = cell_count_of(axes);
    CellLines lines(axes, cells);
    CellSet oracle(cells);
    const int sets = std::uniform_int_distribution<int>(0, 4)(run.rng());
    for (int k = 0; k < sets; ++k) {
      CellSet set = random_runs(run.rng(), cells, axes.cells[0]);
      if (std::bernoulli_distribution(0.5)(run.rng()) && axes.count > 1) {
        // Independent of the last axis, so that a lower level is written.
        const std::uint32_t last = axes.count - 1;
        set = repeat_slice(cells_in_every_slice(set, axes.stride[last], axes.cells[last]),
                           axes.cells[last]);
        set |= random_runs(run.rng(), cells, axes.cells[0]);
      }
      add(lines, set, axes);
      oracle |= set;
    }
    CellSet packed(cells);
    packed.fill();  // pack_into overwrites what was there
    lines.pack_into(packed);
    ASSERT_EQ(packed, oracle) << "grid of " << cells << " cells, joint 0 has " << axes.cells[0];
    lines.clear();
    lines.pack_into(packed);
    ASSERT_FALSE(packed.any());
  }
}

// Runs that begin or end on a word's edge, in lines of exactly one and two words and one cell
// more: where the run writer and the packer change words (random draws rarely land there).
TEST(CellLines, RunsOnWordEdgesPackToTheirCells) {
  struct Run {
    std::uint32_t first;
    std::uint32_t end;  // one past the last cell
  };
  const Run runs[] = {{0, 64}, {63, 65}, {64, 128},  {0, 128}, {1, 127}, {127, 128},
                      {0, 1},  {64, 65}, {128, 130}, {0, 130}, {63, 64}};
  for (const std::uint32_t line_cells : {64U, 65U, 128U, 129U, 130U}) {
    BoxAxes axes;
    axes.count = 2;
    axes.joint[0] = 0;
    axes.joint[1] = 1;
    axes.stride[0] = 1;
    axes.stride[1] = line_cells;
    axes.cells[0] = line_cells;
    axes.cells[1] = 3;
    const CellIndex cells = cell_count_of(axes);
    for (const Run& run : runs) {
      if (run.end > line_cells) continue;
      for (CellIndex line = 0; line < 3; ++line) {
        CellSet set(cells);
        set.set_range(line * line_cells + run.first, line * line_cells + run.end);
        CellLines lines(axes, cells);
        add(lines, set, axes);
        CellSet packed(cells);
        packed.fill();
        lines.pack_into(packed);
        ASSERT_EQ(packed, set) << "lines of " << line_cells << " cells, run " << run.first << ".."
                               << run.end - 1 << " in line " << line;
      }
    }
  }
}

TEST(CellLines, ContainsIsTheSubsetRelation) {
  BoxAxes axes;
  axes.count = 2;
  axes.stride[0] = 1;
  axes.cells[0] = 70;
  axes.stride[1] = 70;
  axes.cells[1] = 4;
  CellLines small(axes, 280);
  CellLines large(axes, 280);
  CellSet small_cells(280);
  // Cells 62..67 of lines 0 and 1: across the boundary of the line's first word.
  small_cells.set_range(62, 68);
  small_cells.set_range(70 + 62, 70 + 68);
  CellSet large_cells(280);
  for (CellIndex line = 0; line < 3; ++line) large_cells.set_range(line * 70 + 50, line * 70 + 70);
  add(small, small_cells, axes);
  CellLines empty(axes, 280);
  EXPECT_TRUE(small.contains(empty));
  EXPECT_FALSE(large.contains(small));
  add(large, large_cells, axes);
  EXPECT_TRUE(large.contains(small));
  EXPECT_FALSE(small.contains(large));
}

TEST(CellLines, ALowerLevelLineStandsForAllItsCopies) {
  BoxAxes axes;
  axes.count = 3;
  axes.stride[0] = 1;
  axes.cells[0] = 10;
  axes.stride[1] = 10;
  axes.cells[1] = 6;
  axes.stride[2] = 60;
  axes.cells[2] = 7;
  CellLines lines(axes, 420);
  // Line 1 + 1 of the lines (level 1 has one line): joint 1 at 1, cells 3..5 along joint 0.
  std::vector<std::uint8_t> bytes;
  const LineRun run{3, 3};
  PixelToCellsTable::append_strip(bytes, 0, 2, std::span<const LineRun>(&run, 1));
  EXPECT_EQ(lines.add_strips(bytes.data(), bytes.data() + bytes.size()), 1U);
  EXPECT_THROW((void)lines.lines(), std::logic_error);  // not folded yet
  CellSet packed(420);
  lines.pack_into(packed);
  CellSet expected(420);
  for (CellIndex copy = 0; copy < 7; ++copy) expected.set_range(copy * 60 + 13, copy * 60 + 16);
  EXPECT_EQ(packed, expected);
}

// Fusion votes on a part moved by the first joints at the level its sets were written at, and
// folds the result (fold_to, level_lines, level_lines_to_add_to): the same bits as folding each
// set whole. The sets then lie above the level they were written at, and clear() must clear them.
TEST(CellLines, ASetFoldedToALevelHoldsTheSameCellsAndClearsWhole) {
  test::PropertyRun run(300);
  for (int i = 0; i < run.iterations(); ++i) {
    BoxAxes axes = random_axes(run.rng());
    if (axes.count < 2) continue;
    const CellIndex cells = cell_count_of(axes);
    const std::uint32_t last = axes.count - 1;
    CellLines lines(axes, cells);
    CellSet oracle(cells);
    const int sets = std::uniform_int_distribution<int>(1, 3)(run.rng());
    for (int k = 0; k < sets; ++k) {
      // Independent of the last axis, so that it is written below the full grid.
      const CellSet set =
          repeat_slice(cells_in_every_slice(random_runs(run.rng(), cells, axes.cells[0]),
                                            axes.stride[last], axes.cells[last]),
                       axes.cells[last]);
      add(lines, set, axes);
      oracle |= set;
    }
    const std::uint32_t through = lines.written_through();
    const std::uint32_t level = std::uniform_int_distribution<std::uint32_t>(
        std::max<std::uint32_t>(through, 1), axes.count)(run.rng());
    const std::string input = "grid of " + std::to_string(cells) + " cells, " +
                              std::to_string(axes.count) + " axes, joint 0 has " +
                              std::to_string(axes.cells[0]) + ", written through level " +
                              std::to_string(through) + ", folded to " + std::to_string(level);
    ASSERT_LT(through, axes.count) << input;
    if (through > 1) {
      EXPECT_THROW(lines.fold_to(through - 1), std::logic_error) << input;
    }
    lines.fold_to(level);
    EXPECT_EQ(lines.folded(), level == axes.count || oracle.count() == 0) << input;
    // The level's lines, added to another set at that level, stand for the same cells.
    CellLines voted(axes, cells);
    const std::span<const std::uint64_t> at_level = lines.level_lines(level);
    const std::span<std::uint64_t> into = voted.level_lines_to_add_to(level);
    ASSERT_EQ(into.size(), at_level.size()) << input;
    std::copy(at_level.begin(), at_level.end(), into.begin());
    CellSet packed(cells);
    voted.pack_into(packed);
    ASSERT_EQ(packed, oracle) << input;
    CellLines whole = lines;
    whole.pack_into(packed);
    ASSERT_EQ(packed, oracle) << input;
    // Cleared, and written again: nothing of the bits folded up to the level may stay.
    lines.clear();
    const CellSet again = random_runs(run.rng(), cells, axes.cells[0]);
    add(lines, again, axes);
    lines.pack_into(packed);
    ASSERT_EQ(packed, again) << input << ", cleared";
  }
}

TEST(CellLines, OneWordPerLineUpTo64CellsAlongJointZero) {
  BoxAxes axes;
  axes.count = 2;
  axes.stride[0] = 1;
  axes.cells[0] = 64;
  axes.stride[1] = 64;
  axes.cells[1] = 3;
  EXPECT_EQ(CellLines(axes, 192).words_per_line(), 1U);
  axes.cells[0] = 65;
  axes.stride[1] = 65;
  EXPECT_EQ(CellLines(axes, 195).words_per_line(), 2U);
  EXPECT_EQ(CellLines(axes, 195).line_count(), 3U);
}

TEST(CellLines, RefusesAGridThatIsNotWholeLines) {
  BoxAxes axes;
  axes.count = 1;
  axes.stride[0] = 1;
  axes.cells[0] = 10;
  EXPECT_THROW(CellLines(axes, 25), std::invalid_argument);
}

}  // namespace
}  // namespace safecell
