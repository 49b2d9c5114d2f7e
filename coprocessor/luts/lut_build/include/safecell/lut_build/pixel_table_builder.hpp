#pragma once
// Builds LUT-2 from LUT-1 (paper §4.1): for every feature cell, the C-space cells whose
// silhouette holds it, as strips of line runs. The cells of a band of feature rows are gathered as
// one bitset per pixel (the band is sized to a memory budget, so a finer grid streams instead of
// holding everything), then each pixel's bitset is cut into strips (strip_cover.hpp).
//
// The pyramid: besides every pixel's cells, every block of 2 x 2, 4 x 4, ... pixels (aligned to
// multiples of its size) gets the union of its pixels' cells. Fusion adds a whole block where all
// its pixels are obstacles: one block's strips instead of many pixels' mostly repeated ones.
//
// The differences: neighbouring pixels see nearly the same cells. Where the pixel (or block) on
// the left, or the one above, is an obstacle too, fusion has added its cells already and adds
// only what this one adds to them - typically a third to a half of the lines.

#include <array>
#include <cstddef>

#include "safecell/compute/parallel_chunks.hpp"
#include "safecell/cspace/cspace_grid.hpp"
#include "safecell/tables/cell_to_pixels_table.hpp"
#include "safecell/tables/lut_set.hpp"
#include "safecell/tables/neighbour.hpp"
#include "safecell/tables/pixel_to_cells_table.hpp"

namespace safecell {

inline constexpr int kMaxBlockLevels = 6;

struct PixelTableBuild {
  unsigned threads = 0;                          // 0: one per hardware thread
  std::size_t memory_budget_bytes = 256u << 20;  // for the per-pixel bitsets of one band
  int block_levels = 3;                          // blocks of 2, 4 and 8 pixels a side
};

// LUT-2 of one part, its block levels and their differences (lut_set.hpp) from the part's LUT-1.
// Differences: nothing in the first column (left) or row (upper); the whole entry in the first
// row of a band but the first (upper: the band above is gone by then). Throws
// std::invalid_argument when the table is not of the grid, or for block levels outside
// 0..kMaxBlockLevels.
[[nodiscard]] PartLuts build_pixel_to_cells_tables(const CellToPixelsTable& cell_table,
                                                   const CspaceGrid& grid,
                                                   const PixelTableBuild& build = {},
                                                   const ProgressCallback& progress = {});

}  // namespace safecell
