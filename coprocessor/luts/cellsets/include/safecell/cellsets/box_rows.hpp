#pragma once
// The axes LUT-2 and fusion cut the C-space grid along: joint 0 and every other joint with more
// than one cell. Along axis 0 (joint 0) cells are consecutive indices, so the grid is lines of
// axes.cells[0] cells (line_levels.hpp).

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

}  // namespace safecell
