#pragma once
// LUT-2 of one camera (the paper's Figure 4): for every feature cell ("pixel"), the C-space cells
// in which the robot can cover it, coded as boxes of cells (the paper's 6-D boxes). Fusion ORs
// the boxes of every blocked pixel into the camera's cell set.
//
// Box coding (box_rows.hpp): the box axes are joint 0 and every other joint with more than one
// cell. A box is 4 + axes bytes: its lowest cell index (32 bits, little-endian), then its extent
// in cells along each box axis (1..255). Along joint 0 a box is a run of consecutive cell
// indices, so adding a box costs one bit-range fill per row of cells it spans.
//
// A view, like CellToPixelsTable: the arrays live in vectors or a mapped file.

#include <cstdint>
#include <memory>
#include <span>
#include <vector>

#include "safecell/cspace/cspace_grid.hpp"
#include "safecell/lut/box_rows.hpp"
#include "safecell/lut/cell_set.hpp"

namespace safecell {

class PixelToCellsTable {
 public:
  PixelToCellsTable() = default;
  // Owns the arrays. offsets: pixel_count + 1 ascending box counts (pixel = row * columns +
  // column); box_bytes: the boxes. Throws std::invalid_argument when they do not fit together or
  // a box leaves the grid.
  PixelToCellsTable(const CspaceGrid& grid, int columns, int rows,
                    std::vector<std::uint64_t> offsets, std::vector<std::uint8_t> box_bytes);
  PixelToCellsTable(const CspaceGrid& grid, int columns, int rows,
                    std::span<const std::uint64_t> offsets, std::span<const std::uint8_t> box_bytes,
                    std::shared_ptr<const void> storage);

  [[nodiscard]] int columns() const { return columns_; }
  [[nodiscard]] int rows() const { return rows_; }
  [[nodiscard]] std::size_t pixel_count() const { return offsets_.size() - 1; }
  [[nodiscard]] std::uint32_t cell_count() const { return cell_count_; }
  [[nodiscard]] const BoxAxes& axes() const { return axes_; }
  [[nodiscard]] std::uint64_t box_count(std::size_t pixel) const {
    return offsets_[pixel + 1] - offsets_[pixel];
  }
  [[nodiscard]] std::uint64_t total_boxes() const { return offsets_.back(); }

  // ORs the cells of one pixel into `cells` (precondition: pixel < pixel_count(), cells of the
  // table's grid). The hot loop of fusion.
  void add_cells(std::size_t pixel, CellSet& cells) const;
  // Calls visit(cell) for every cell of the pixel, box by box (slow; for tests and baselines).
  template <typename Visit>
  void for_each_cell(std::size_t pixel, Visit visit) const;

  [[nodiscard]] static CellIndex box_start(const std::uint8_t* box) {
    return static_cast<CellIndex>(box[0]) | (static_cast<CellIndex>(box[1]) << 8) |
           (static_cast<CellIndex>(box[2]) << 16) | (static_cast<CellIndex>(box[3]) << 24);
  }

  [[nodiscard]] std::span<const std::uint64_t> offsets() const { return offsets_; }
  [[nodiscard]] std::span<const std::uint8_t> box_bytes() const { return box_bytes_; }
  [[nodiscard]] std::size_t bytes() const {
    return offsets_.size_bytes() + box_bytes_.size_bytes();
  }

 private:
  void check() const;

  int columns_ = 0;
  int rows_ = 0;
  std::uint32_t cell_count_ = 0;
  BoxAxes axes_;
  std::span<const std::uint64_t> offsets_;
  std::span<const std::uint8_t> box_bytes_;
  std::shared_ptr<const void> storage_;
};

template <typename Visit>
void PixelToCellsTable::for_each_cell(std::size_t pixel, Visit visit) const {
  const std::uint32_t bytes_per_box = axes_.bytes_per_box();
  for (std::uint64_t box = offsets_[pixel]; box < offsets_[pixel + 1]; ++box) {
    const std::uint8_t* bytes = box_bytes_.data() + box * bytes_per_box;
    for_each_box_row(axes_, box_start(bytes), bytes + 4, [&](CellIndex first, std::uint32_t run) {
      for (std::uint32_t i = 0; i < run; ++i) visit(first + i);
    });
  }
}

}  // namespace safecell
