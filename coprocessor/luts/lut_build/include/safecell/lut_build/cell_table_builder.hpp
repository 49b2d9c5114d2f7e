#pragma once
// Builds LUT-1 of every camera from a source of silhouettes: whatever says, for one C-space cell,
// which feature cells of each camera the robot covers (the robot model in model mode, difference
// images of the real robot in recorded mode). Parallel over cells.

#include <cstdint>
#include <functional>
#include <vector>

#include "safecell/compute/parallel_chunks.hpp"
#include "safecell/features/feature_mask.hpp"
#include "safecell/tables/cell_to_pixels_table.hpp"

namespace safecell {

// Fills masks[table] (cleared and of the grid's size on entry) for one cell: one table per camera,
// or per robot part and camera (part-major). Called from several threads at once.
using CellSilhouettes = std::function<void(CellIndex cell, std::vector<FeatureMask>& masks)>;

struct CellTableBuild {
  std::uint32_t cell_count = 0;
  std::size_t table_count = 0;  // cameras, or parts x cameras
  int columns = 0;              // the feature grid
  int rows = 0;
  unsigned threads = 0;  // 0: one per hardware thread
};

// The tables, in the order of the masks.
[[nodiscard]] std::vector<CellToPixelsTable> build_cell_to_pixels_tables(
    const CellTableBuild& build, const CellSilhouettes& silhouettes,
    const ProgressCallback& progress = {});

// LUT-1 of table.cell_count() * times cells, cell c with the rectangles of cell
// c % table.cell_count(). For a robot part that only the first joints move: with joint 0 the
// fastest in a cell's index, the cells that differ only in the other joints' cells follow each
// other at that period, and their silhouettes of the part are the same. Throws
// std::invalid_argument when the result would have more than 2^32 - 1 cells.
[[nodiscard]] CellToPixelsTable repeat_cells(const CellToPixelsTable& table, std::uint32_t times);

}  // namespace safecell
