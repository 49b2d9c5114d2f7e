#include "safecell/lut/cell_lines.hpp"

#include <gtest/gtest.h>

#include <random>

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

TEST(CellLines, PackedBoxesEqualTheBoxesSetRowByRow) {
  test::PropertyRun run(300);
  for (int i = 0; i < run.iterations(); ++i) {
    const BoxAxes axes = random_axes(run.rng());
    const CellIndex cells = cell_count_of(axes);
    CellLines lines(axes, cells);
    CellSet oracle(cells);
    const int boxes = std::uniform_int_distribution<int>(0, 6)(run.rng());
    for (int b = 0; b < boxes; ++b) {
      CellIndex start = 0;
      std::uint8_t extents[kMaxJoints]{};
      for (std::uint32_t axis = 0; axis < axes.count; ++axis) {
        const auto low =
            std::uniform_int_distribution<std::uint32_t>(0, axes.cells[axis] - 1)(run.rng());
        const auto extent = std::uniform_int_distribution<std::uint32_t>(
            1, std::min<std::uint32_t>(255, axes.cells[axis] - low))(run.rng());
        start += low * axes.stride[axis];
        extents[axis] = static_cast<std::uint8_t>(extent);
      }
      lines.add_box(start, extents);
      for_each_box_row(axes, start, extents, [&](CellIndex first, std::uint32_t run_cells) {
        oracle.set_range(first, first + run_cells);
      });
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

TEST(CellLines, ContainsIsTheSubsetRelation) {
  BoxAxes axes;
  axes.count = 2;
  axes.stride[0] = 1;
  axes.cells[0] = 70;
  axes.stride[1] = 70;
  axes.cells[1] = 4;
  CellLines small(axes, 280);
  CellLines large(axes, 280);
  const std::uint8_t small_box[] = {5, 2};
  const std::uint8_t large_box[] = {30, 3};
  small.add_box(66, small_box);  // cells 66..70 of lines 0 and 1: across the word boundary
  CellLines empty(axes, 280);
  EXPECT_TRUE(small.contains(empty));
  EXPECT_FALSE(large.contains(small));
  EXPECT_EQ(large.add_box(50, large_box), 3U);
  EXPECT_TRUE(large.contains(small));
  EXPECT_FALSE(small.contains(large));
}

TEST(CellLines, ABoxSpanningTheTrailingAxesWholeCostsItsLeadingLines) {
  BoxAxes axes;
  axes.count = 3;
  axes.stride[0] = 1;
  axes.cells[0] = 10;
  axes.stride[1] = 10;
  axes.cells[1] = 6;
  axes.stride[2] = 60;
  axes.cells[2] = 7;
  CellLines lines(axes, 420);
  const std::uint8_t whole_along_axis_2[] = {3, 2, 7};
  const std::uint8_t whole_along_axes_1_and_2[] = {2, 6, 7};
  EXPECT_EQ(lines.add_box(14, whole_along_axis_2), 2U);       // lines 1 and 2 of level 2
  EXPECT_EQ(lines.add_box(7, whole_along_axes_1_and_2), 1U);  // the one line of level 1
  CellSet oracle(420);
  for_each_box_row(axes, 14, whole_along_axis_2, [&](CellIndex first, std::uint32_t run) {
    oracle.set_range(first, first + run);
  });
  for_each_box_row(axes, 7, whole_along_axes_1_and_2, [&](CellIndex first, std::uint32_t run) {
    oracle.set_range(first, first + run);
  });
  CellSet packed(420);
  lines.pack_into(packed);
  EXPECT_EQ(packed, oracle);
  EXPECT_EQ(packed.count(), 3U * 2U * 7U + 2U * 6U * 7U);
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
