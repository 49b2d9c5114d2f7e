#pragma once
// Cuts a set of C-space cells into the boxes of LUT-2 (pixel_to_cells_table.hpp).
//
// Fusion pays per line of a box (cell_lines.hpp), and a box that spans the whole range of the
// trailing box axes costs only the lines of its leading axes there. So the set is first split by
// the joints it does not depend on: level d holds the cells of the first d axes whose every cell
// along the remaining axes is in the set (the robot's upper arm does not move with joints 3 and
// 4: much of a pixel's set is such a product). Each level is cut into boxes over its own axes,
// extended over the whole of the remaining ones, leaving out what the level below already
// covers. Within a level, a box grows greedily from its lowest uncovered cell: along joint 0 over
// the whole run of the set (covered or not), then along each further axis while the new layer
// lies in the set and is not all covered already. Boxes may overlap; they never leave the set.

#include <cstddef>
#include <cstdint>
#include <vector>

#include "safecell/lut/box_rows.hpp"
#include "safecell/lut/cell_set.hpp"

namespace safecell {

// The boxes of `cells`, appended to `box_bytes` in the coding of PixelToCellsTable (ascending
// lowest cell). Returns the number of boxes.
std::size_t append_boxes(const CellSet& cells, const BoxAxes& axes,
                         std::vector<std::uint8_t>& box_bytes);

}  // namespace safecell
