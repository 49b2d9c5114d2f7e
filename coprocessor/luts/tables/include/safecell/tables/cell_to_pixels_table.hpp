#pragma once
// LUT-1 of one camera (the paper's Figure 3): for every C-space cell, the feature cells the robot
// can cover while its configuration is anywhere in that cell, coded as non-overlapping
// rectangles (the paper's r(u_beg, v_beg, u_end, v_end)). Robot removal reads one row per cycle.
//
// The table is a view: its arrays live in vectors or in a mapped LUT file, kept alive by the
// table (copies share them).

#include <cstdint>
#include <memory>
#include <span>
#include <vector>

#include "safecell/cspace/cspace_grid.hpp"
#include "safecell/features/feature_mask.hpp"

namespace safecell {

class CellToPixelsTable {
 public:
  CellToPixelsTable() = default;
  // Owns the arrays. offsets: cell_count + 1 ascending entries from 0 to rects.size(); rect i of
  // cell c is rects[offsets[c] + i]. Throws std::invalid_argument when they do not fit together
  // or a rectangle leaves the mask.
  CellToPixelsTable(int columns, int rows, std::vector<std::uint64_t> offsets,
                    std::vector<FeatureRect> rects);
  // A view of arrays kept alive by `storage` (a mapped file); checked as above.
  CellToPixelsTable(int columns, int rows, std::span<const std::uint64_t> offsets,
                    std::span<const FeatureRect> rects, std::shared_ptr<const void> storage);

  [[nodiscard]] int columns() const { return columns_; }
  [[nodiscard]] int rows() const { return rows_; }
  [[nodiscard]] std::uint32_t cell_count() const {
    return offsets_.empty() ? 0 : static_cast<std::uint32_t>(offsets_.size() - 1);
  }
  [[nodiscard]] std::span<const FeatureRect> rects_of(CellIndex cell) const {
    return rects_.subspan(offsets_[cell], offsets_[cell + 1] - offsets_[cell]);
  }
  // Adds the cell's feature cells to `mask` (precondition: the table's size, cell < cell_count).
  void add_to(CellIndex cell, FeatureMask& mask) const;
  [[nodiscard]] FeatureMask mask_of(CellIndex cell) const;
  // (cell, feature cell) pairs: the entries an uncompressed LUT-1 would hold.
  [[nodiscard]] std::uint64_t covered_pairs() const;

  [[nodiscard]] std::span<const std::uint64_t> offsets() const { return offsets_; }
  [[nodiscard]] std::span<const FeatureRect> rects() const { return rects_; }
  [[nodiscard]] std::size_t bytes() const { return offsets_.size_bytes() + rects_.size_bytes(); }

 private:
  void check() const;

  int columns_ = 0;
  int rows_ = 0;
  std::span<const std::uint64_t> offsets_;
  std::span<const FeatureRect> rects_;
  std::shared_ptr<const void> storage_;
};

}  // namespace safecell
