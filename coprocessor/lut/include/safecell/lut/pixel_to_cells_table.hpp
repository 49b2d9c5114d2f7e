#pragma once
// LUT-2 of one camera (the paper's Figure 4): for every feature cell ("pixel") - or, at the
// coarser levels of the pyramid (cell_pyramid.hpp), every block of pixels - the C-space cells in
// which the robot can cover it, coded as boxes of cells (the paper's 6-D boxes). Fusion ORs the
// boxes of every blocked pixel into the camera's cell set.
//
// Box coding (box_rows.hpp): the box axes are joint 0 and every other joint with more than one
// cell. A pixel's boxes come in ascending order of their lowest cell; each is that cell as the
// difference to the previous box's (the first: to 0) in LEB128 (7 bits a byte, low first), then
// one extent byte per box axis (1..255). Along joint 0 a box is a run of consecutive cell
// indices, so adding a box costs one bit-range fill per row of cells it spans.
//
// A view, like CellToPixelsTable: the arrays live in vectors or a mapped file.

#include <cstdint>
#include <memory>
#include <span>
#include <vector>

#include "safecell/cspace/cspace_grid.hpp"
#include "safecell/lut/box_rows.hpp"
#include "safecell/lut/cell_lines.hpp"
#include "safecell/lut/cell_set.hpp"

namespace safecell {

class PixelToCellsTable {
 public:
  PixelToCellsTable() = default;
  // Owns the arrays. offsets: pixel_count + 1 ascending byte offsets into box_bytes (pixel = row
  // * columns + column). Throws std::invalid_argument when they do not fit together or a box is
  // malformed or leaves the grid (every box is decoded once here).
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
  [[nodiscard]] std::uint64_t total_boxes() const { return total_boxes_; }

  // ORs the cells of one pixel into `cells` (precondition: pixel < pixel_count(), cells of the
  // table's grid). The hot loop of fusion.
  void add_cells(std::size_t pixel, CellSet& cells) const;
  // The same into the line layout (cell_lines.hpp), which fills boxes faster. Returns the number
  // of lines the pixel's boxes span.
  std::size_t add_cells(std::size_t pixel, CellLines& cells) const;
  // Calls visit(lowest cell, extents) for every box of the pixel.
  template <typename Visit>
  void for_each_box(std::size_t pixel, Visit visit) const;
  // Calls visit(cell) for every cell of the pixel, box by box (slow; for tests and baselines).
  template <typename Visit>
  void for_each_cell(std::size_t pixel, Visit visit) const;

  // Appends one box in the coding above; `previous_start` is the lowest cell of the pixel's box
  // before it (0 for its first), `start` >= previous_start.
  static void append_box(std::vector<std::uint8_t>& bytes, CellIndex previous_start,
                         CellIndex start, const std::uint32_t* extents, std::uint32_t axes);

  [[nodiscard]] std::span<const std::uint64_t> offsets() const { return offsets_; }
  [[nodiscard]] std::span<const std::uint8_t> box_bytes() const { return box_bytes_; }
  [[nodiscard]] std::size_t bytes() const {
    return offsets_.size_bytes() + box_bytes_.size_bytes();
  }

 private:
  void check();

  int columns_ = 0;
  int rows_ = 0;
  std::uint32_t cell_count_ = 0;
  BoxAxes axes_;
  std::uint64_t total_boxes_ = 0;
  std::span<const std::uint64_t> offsets_;
  std::span<const std::uint8_t> box_bytes_;
  std::shared_ptr<const void> storage_;
};

template <typename Visit>
void PixelToCellsTable::for_each_box(std::size_t pixel, Visit visit) const {
  const std::uint8_t* byte = box_bytes_.data() + offsets_[pixel];
  const std::uint8_t* const end = box_bytes_.data() + offsets_[pixel + 1];
  CellIndex start = 0;
  while (byte != end) {
    CellIndex delta = 0;
    for (int shift = 0;; shift += 7) {
      delta |= static_cast<CellIndex>(*byte & 0x7FU) << shift;
      if ((*byte++ & 0x80U) == 0) break;
    }
    start += delta;
    visit(start, byte);
    byte += axes_.count;
  }
}

template <typename Visit>
void PixelToCellsTable::for_each_cell(std::size_t pixel, Visit visit) const {
  for_each_box(pixel, [&](CellIndex start, const std::uint8_t* extents) {
    for_each_box_row(axes_, start, extents, [&](CellIndex first, std::uint32_t run) {
      for (std::uint32_t i = 0; i < run; ++i) visit(first + i);
    });
  });
}

}  // namespace safecell
