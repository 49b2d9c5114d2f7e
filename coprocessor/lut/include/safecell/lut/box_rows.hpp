#pragma once
// The rows of a box of C-space cells: a box starts at its lowest cell and spans extents[a] cells
// along box axis a (BoxAxes); along axis 0 (joint 0) its cells are consecutive indices, so the box
// is a set of runs ("rows") of extents[0] cells.

#include <cstdint>

#include "safecell/cspace/cspace_grid.hpp"

namespace safecell {

struct BoxAxes {
  std::uint32_t count = 0;
  std::uint32_t joint[kMaxJoints]{};
  CellIndex stride[kMaxJoints]{};
  std::uint32_t cells[kMaxJoints]{};

  // Joint 0 and every other joint with more than one cell.
  static BoxAxes of(const CspaceGrid& grid);
};

// Calls row(first cell, run length) for every row of the box, in ascending cell order.
template <typename Extent, typename Row>
void for_each_box_row(const BoxAxes& axes, CellIndex start, const Extent* extents, Row row) {
  const auto run = static_cast<std::uint32_t>(extents[0]);
  std::uint32_t at[kMaxJoints]{};  // an odometer over the axes after joint 0
  CellIndex first = start;
  while (true) {
    row(first, run);
    std::uint32_t axis = 1;
    for (; axis < axes.count; ++axis) {
      if (++at[axis] < static_cast<std::uint32_t>(extents[axis])) {
        first += axes.stride[axis];
        break;
      }
      first -= (at[axis] - 1) * axes.stride[axis];
      at[axis] = 0;
    }
    if (axis >= axes.count) return;
  }
}

}  // namespace safecell
