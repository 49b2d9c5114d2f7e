#pragma once
// Cuts a set of C-space cells into the strips of LUT-2 (the coding of pixel_to_cells_table.hpp).
//
// Fusion pays per line, and a line of a lower level (line_levels.hpp) stands for all its copies
// along the trailing axes. So the set is first split by the joints it does not depend on: level d
// holds the cells of the first d axes whose every cell along the remaining axes is in the set
// (the robot's upper arm does not move with joints 3 and 4: much of a pixel's set is such a
// product). In each level, every maximal run of the level's cells in a line becomes a run of
// LUT-2, unless the level below (or a set known to be there already) covers all of it; the j-th
// run of consecutive lines goes into one strip.

#include <cstddef>
#include <cstdint>
#include <vector>

#include "safecell/cellsets/box_rows.hpp"
#include "safecell/cellsets/cell_set.hpp"

namespace safecell {

// The strips of `cells` (a set of the grid of `axes`), appended to `strip_bytes`. Returns the
// number of strips. With `known` (of the same grid): only what `cells` adds to a set that holds
// `known` already - runs all of whose cells are known are left out, the others still run over
// the set's cells whole (for LUT-2's differences to a neighbour, pixel_table_builder.hpp).
std::size_t append_strips(const CellSet& cells, const BoxAxes& axes,
                          std::vector<std::uint8_t>& strip_bytes, const CellSet* known = nullptr);

}  // namespace safecell
