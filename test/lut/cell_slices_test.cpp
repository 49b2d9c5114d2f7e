#include "safecell/cellsets/cell_slices.hpp"

#include <gtest/gtest.h>

#include <random>
#include <stdexcept>

#include "safecell/test/property.hpp"

namespace safecell {
namespace {

TEST(CellSlices, CellsInEverySliceAndRepeatedSlicesAgreeWithCellByCell) {
  test::PropertyRun run(200);
  for (int i = 0; i < run.iterations(); ++i) {
    const auto slice_cells = std::uniform_int_distribution<std::uint32_t>(1, 200)(run.rng());
    const auto slices = std::uniform_int_distribution<std::uint32_t>(1, 7)(run.rng());
    // Mostly full, so that cells in every slice exist.
    const double density = std::uniform_real_distribution<double>(0.5, 1.0)(run.rng());
    CellSet cells(slice_cells * slices);
    for (CellIndex c = 0; c < cells.cell_count(); ++c) {
      if (std::bernoulli_distribution(density)(run.rng())) cells.set(c);
    }
    const CellSet common = cells_in_every_slice(cells, slice_cells, slices);
    ASSERT_EQ(common.cell_count(), slice_cells);
    for (CellIndex x = 0; x < slice_cells; ++x) {
      bool everywhere = true;
      for (std::uint32_t k = 0; k < slices; ++k)
        everywhere = everywhere && cells.test(x + k * slice_cells);
      ASSERT_EQ(common.test(x), everywhere) << "cell " << x << " of slices of " << slice_cells;
    }
    const CellSet repeated = repeat_slice(common, slices);
    ASSERT_EQ(repeated.cell_count(), cells.cell_count());
    for (CellIndex c = 0; c < repeated.cell_count(); ++c) {
      ASSERT_EQ(repeated.test(c), common.test(c % slice_cells)) << "cell " << c;
    }
  }
}

TEST(CellSlices, RefusesSlicesThatDoNotTileTheSet) {
  EXPECT_THROW((void)cells_in_every_slice(CellSet(10), 3, 3), std::invalid_argument);
}

}  // namespace
}  // namespace safecell
