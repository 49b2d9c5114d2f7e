#include "safecell/lut_build/pixel_table_check.hpp"

#include <gtest/gtest.h>

#include <algorithm>

#include "safecell/cell/cell_grid.hpp"
#include "safecell/cell/cell_model.hpp"
#include "safecell/cell/default_cell.hpp"
#include "safecell/lut_build/model_luts.hpp"

namespace safecell {
namespace {

// A window of the default cell's grid at m_max = 6 cm, the fine grid of the precision targets:
// the cells are of that size, only fewer (joints 1-3 narrowed to a few dozen degrees around the
// arm's upright pose, joint 4 whole), so that every cell can be checked.
CellModel fine_window_cell() {
  CellConfig config = default_cell();
  config.m_max_m = 0.06;
  config.joints.at(0).range_deg = std::array<double, 2>{-15.0, 15.0};
  config.joints.at(1).range_deg = std::array<double, 2>{-10.0, 20.0};
  config.joints.at(2).range_deg = std::array<double, 2>{60.0, 90.0};
  return load_cell_model(config);
}

class PixelTableCheckTest : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    cell_ = new CellModel(fine_window_cell());
    grid_ = new CspaceGrid(make_grid(cell_->config));
    luts_ = new LutSet(build_model_luts(*cell_, *grid_, ModelLutOptions{}));
    silhouettes_ = new ModelSilhouettes(*cell_, *grid_, ModelLutOptions{});
  }
  static void TearDownTestSuite() {
    delete silhouettes_;
    delete luts_;
    delete grid_;
    delete cell_;
  }

  // 400 cells spread over the window (every k-th), the last cell among them: each is compared
  // in every feature cell, block and difference entry of every camera and part.
  static std::vector<CellIndex> spread_cells() {
    const CellIndex step = std::max<CellIndex>(1, grid_->cell_count() / 400);
    std::vector<CellIndex> cells;
    for (CellIndex cell = 0; cell < grid_->cell_count(); cell += step) cells.push_back(cell);
    cells.push_back(grid_->cell_count() - 1);
    return cells;
  }

  static CellModel* cell_;
  static CspaceGrid* grid_;
  static LutSet* luts_;
  static ModelSilhouettes* silhouettes_;
};

CellModel* PixelTableCheckTest::cell_ = nullptr;
CspaceGrid* PixelTableCheckTest::grid_ = nullptr;
LutSet* PixelTableCheckTest::luts_ = nullptr;
ModelSilhouettes* PixelTableCheckTest::silhouettes_ = nullptr;

// The window is a real slice of the 6 cm grid: its joints' cells are as wide as the full grid's
// (at most the step the 6 cm max-move allows, and not much less).
TEST_F(PixelTableCheckTest, TheWindowHasTheCellsOfTheSixCentimetreGrid) {
  CellConfig full = default_cell();
  full.m_max_m = 0.06;
  const CspaceGrid full_grid = make_grid(load_cell_model(full).config);
  const GridCoords first = grid_->coords_of(0).value();
  for (std::uint32_t j = 0; j < 4; ++j) {
    const AngleInterval cell = grid_->cell_bounds(first, j).value();
    const double width = cell.hi_rad - cell.lo_rad;
    EXPECT_LE(width, full_grid.max_move_step_rad(j) * (1 + 1e-9)) << "joint " << j;
    EXPECT_GE(width, 0.8 * full_grid.max_move_step_rad(j)) << "joint " << j;
  }
  EXPECT_GT(grid_->cell_count(), 2000U);
  EXPECT_GT(full_grid.cell_count(), 14'000'000U);
}

TEST_F(PixelTableCheckTest, TheFineTablesNameEachCellWhereItsSilhouetteIs) {
  const PixelTableCheck check = check_pixel_tables(*luts_, *silhouettes_, spread_cells(), 2);
  EXPECT_EQ(check.cells, spread_cells().size());
  EXPECT_GT(check.pairs, std::uint64_t{check.cells} * 4096 * 4 * 3);
  EXPECT_TRUE(check.passed()) << check.mismatches << " mismatches, the first: "
                              << (check.first_mismatches.empty()
                                      ? std::string()
                                      : describe(check.first_mismatches.front(), *luts_));
}

// Negative control: one pixel's entry emptied in one camera's part. The check names it.
TEST_F(PixelTableCheckTest, AnEntryMissingItsCellsIsCaught) {
  LutSet broken = *luts_;
  PartLuts& part = broken.cameras.at(2).parts.at(1);
  const PixelToCellsTable& table = part.pixel_to_cells;
  // The pixel with the most cells of the part: the sampled cells cannot all miss it.
  std::size_t pixel = 0;
  for (std::size_t p = 0; p < table.pixel_count(); ++p) {
    if (table.entry_bytes(p) > table.entry_bytes(pixel)) pixel = p;
  }
  ASSERT_LT(pixel, table.pixel_count());
  std::vector<std::uint64_t> offsets(table.offsets().begin(), table.offsets().end());
  std::vector<std::uint8_t> bytes(table.strip_bytes().begin(), table.strip_bytes().end());
  const std::uint64_t removed = offsets[pixel + 1] - offsets[pixel];
  bytes.erase(bytes.begin() + static_cast<std::ptrdiff_t>(offsets[pixel]),
              bytes.begin() + static_cast<std::ptrdiff_t>(offsets[pixel + 1]));
  for (std::size_t i = pixel + 1; i < offsets.size(); ++i) offsets[i] -= removed;
  part.pixel_to_cells = PixelToCellsTable(*grid_, table.columns(), table.rows(), std::move(offsets),
                                          std::move(bytes));

  const PixelTableCheck check = check_pixel_tables(broken, *silhouettes_, spread_cells(), 2);
  ASSERT_FALSE(check.passed());
  const PixelTableMismatch& first = check.first_mismatches.front();
  EXPECT_EQ(first.camera, 2U);
  EXPECT_EQ(first.part, 1U);
  EXPECT_EQ(first.level, 0);
  EXPECT_EQ(first.entry, PixelTableEntry::kCells);
  EXPECT_EQ(static_cast<std::size_t>(first.row * table.columns() + first.column), pixel);
  EXPECT_FALSE(first.named);
  EXPECT_NE(describe(first, broken).find("camera cam2"), std::string::npos)
      << describe(first, broken);
}

// Negative control the other way: silhouettes without the padding the tables were built with.
// The tables' cell entries then name cells in feature cells the tighter silhouettes do not reach.
// (A difference entry can go either way: it leaves out a cell its neighbour's larger silhouette
// holds, where the tighter silhouettes say the neighbour does not.)
TEST_F(PixelTableCheckTest, TablesOfALargerRobotAreCaught) {
  ModelLutOptions tighter;
  tighter.padding_m = 0.0;
  const ModelSilhouettes tight(*cell_, *grid_, tighter);
  const PixelTableCheck check = check_pixel_tables(*luts_, tight, spread_cells(), 2);
  ASSERT_FALSE(check.passed());
  std::size_t cell_entries = 0;
  for (const PixelTableMismatch& mismatch : check.first_mismatches) {
    if (mismatch.entry != PixelTableEntry::kCells) continue;
    ++cell_entries;
    EXPECT_TRUE(mismatch.named) << describe(mismatch, *luts_);
  }
  EXPECT_GT(cell_entries, 0U);
}

// The mismatches reported are the table's first, whichever of the threads' chunks ends first:
// one thread and two report the same ones (checked on the control above, which has thousands).
TEST_F(PixelTableCheckTest, TheReportedMismatchesDoNotDependOnTheThreads) {
  ModelLutOptions tighter;
  tighter.padding_m = 0.0;
  const ModelSilhouettes tight(*cell_, *grid_, tighter);
  const PixelTableCheck one = check_pixel_tables(*luts_, tight, spread_cells(), 1);
  const PixelTableCheck two = check_pixel_tables(*luts_, tight, spread_cells(), 2);
  ASSERT_GT(one.mismatches, PixelTableCheck::kMaxReported);
  EXPECT_EQ(one.mismatches, two.mismatches);
  ASSERT_EQ(one.first_mismatches.size(), PixelTableCheck::kMaxReported);
  ASSERT_EQ(two.first_mismatches.size(), PixelTableCheck::kMaxReported);
  for (std::size_t i = 0; i < PixelTableCheck::kMaxReported; ++i) {
    EXPECT_EQ(describe(one.first_mismatches[i], *luts_), describe(two.first_mismatches[i], *luts_))
        << "mismatch " << i;
  }
}

TEST_F(PixelTableCheckTest, ACellOutsideTheGridIsRefused) {
  EXPECT_THROW((void)check_pixel_tables(*luts_, *silhouettes_, {grid_->cell_count()}, 1),
               std::invalid_argument);
}

}  // namespace
}  // namespace safecell
