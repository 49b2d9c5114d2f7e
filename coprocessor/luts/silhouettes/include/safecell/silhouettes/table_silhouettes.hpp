#pragma once
// LUT-1 read from stored tables, one per camera (recorded mode, and tests).

#include <vector>

#include "safecell/silhouettes/robot_silhouettes.hpp"
#include "safecell/tables/cell_to_pixels_table.hpp"

namespace safecell {

class TableSilhouettes final : public RobotSilhouettes {
 public:
  explicit TableSilhouettes(std::vector<CellToPixelsTable> tables) : tables_(std::move(tables)) {}

  [[nodiscard]] std::size_t camera_count() const override { return tables_.size(); }
  // Throws std::out_of_range for a camera or cell outside the tables.
  void add_silhouette(CellIndex cell, std::size_t camera, FeatureMask& mask) const override;

 private:
  std::vector<CellToPixelsTable> tables_;
};

}  // namespace safecell
