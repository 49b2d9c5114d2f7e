#pragma once
// The lines of LUT-2 and of fusion's cell sets. A line is all joint-0 cells at fixed other
// coordinates. Level d (1..axes.count) is the grid of the first d box axes only: a line of level d
// stands for that line at every coordinate of the remaining axes (the cells of a pixel's set that
// do not depend on the trailing joints, pixel_to_cells_table.hpp). The levels' lines are numbered
// one after the other, level 1 first; the top level is the full grid. Lines of a level are
// numbered like the full grid's (joint 1 fastest), so a line of level d with coordinate 0 along
// the axes from d on has the same number within its level as in the full grid.

#include <cstddef>
#include <cstdint>

#include "safecell/cellsets/box_rows.hpp"

namespace safecell {

struct LineLevels {
  std::uint32_t count = 0;       // levels 1..count (one per box axis)
  std::uint32_t line_cells = 1;  // cells along joint 0
  // first_line[d]: number of level d's first line; first_line[count + 1]: all lines.
  std::size_t first_line[kMaxJoints + 2]{};
  // level_cells[d]: cells of the grid of level d (the cells one copy of it spans).
  CellIndex level_cells[kMaxJoints + 1]{};
  CellIndex cell_count = 0;

  // Throws std::invalid_argument when the grid is not whole lines of joint 0.
  static LineLevels of(const BoxAxes& axes, CellIndex cell_count);

  [[nodiscard]] std::size_t total_lines() const { return first_line[count + 1]; }
  [[nodiscard]] std::size_t lines_of(std::uint32_t level) const {
    return first_line[level + 1] - first_line[level];
  }
  // The level holding line `line` (precondition: line < total_lines()).
  [[nodiscard]] std::uint32_t level_of(std::size_t line) const {
    std::uint32_t level = count;
    while (level > 1 && line < first_line[level]) --level;
    return level;
  }
};

}  // namespace safecell
