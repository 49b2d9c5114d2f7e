#pragma once
// Slices of a cell set along its slowest axis. A grid of cells with joint 0 fastest is `slices`
// slices of `slice_cells` consecutive cells each (slice k holds the cells k * slice_cells ..
// (k + 1) * slice_cells - 1); a set over the first axes of a grid, repeated once per slice, is the
// same set extended over the next axis. The LUT-2 strip cover (strip_cover.hpp) uses both to find
// the cells of a set that do not depend on the trailing joints.

#include <cstdint>

#include "safecell/cellsets/cell_set.hpp"

namespace safecell {

// The cells x < slice_cells such that x + k * slice_cells is in `cells` for every k < slices
// (throws std::invalid_argument unless cells.cell_count() == slice_cells * slices).
[[nodiscard]] CellSet cells_in_every_slice(const CellSet& cells, std::uint32_t slice_cells,
                                           std::uint32_t slices);

// `slice` repeated `slices` times: x is in the result when x % slice.cell_count() is in `slice`.
[[nodiscard]] CellSet repeat_slice(const CellSet& slice, std::uint32_t slices);

}  // namespace safecell
