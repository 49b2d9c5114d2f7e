#include "safecell/cellsets/line_levels.hpp"

#include <stdexcept>

namespace safecell {

LineLevels LineLevels::of(const BoxAxes& axes, CellIndex cell_count) {
  if (axes.count == 0 || axes.cells[0] == 0 || cell_count % axes.cells[0] != 0) {
    throw std::invalid_argument("cell lines: the grid has no joint-0 lines");
  }
  LineLevels levels;
  levels.count = axes.count;
  levels.line_cells = axes.cells[0];
  levels.cell_count = cell_count;
  std::size_t lines = 0;
  for (std::uint32_t level = 1; level <= axes.count; ++level) {
    levels.level_cells[level] = level < axes.count ? axes.stride[level] : cell_count;
    levels.first_line[level] = lines;
    lines += levels.level_cells[level] / levels.line_cells;
  }
  levels.first_line[axes.count + 1] = lines;
  return levels;
}

}  // namespace safecell
