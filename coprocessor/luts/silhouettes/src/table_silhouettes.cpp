#include "safecell/silhouettes/table_silhouettes.hpp"

#include <stdexcept>
#include <string>

namespace safecell {

void TableSilhouettes::add_silhouette(CellIndex cell, std::size_t camera, FeatureMask& mask) const {
  const CellToPixelsTable& table = tables_.at(camera);
  if (cell >= table.cell_count()) {
    throw std::out_of_range("cell " + std::to_string(cell) + " outside LUT-1 of " +
                            std::to_string(table.cell_count()) + " cells");
  }
  table.add_to(cell, mask);
}

}  // namespace safecell
