#pragma once
// LUT-2 of one camera (the paper's Figure 4): for every feature cell ("pixel") - or, at the
// coarser levels of the pyramid (pixel_table_builder.hpp), every block of pixels - the C-space
// cells in which the robot can cover it. Fusion ORs the cells of every blocked pixel into the
// camera's cell set (cell_lines.hpp).
//
// Coding. The paper cuts the cells into 6-D boxes; here they are cut into lines of joint-0 cells
// (line_levels.hpp), which is what fusion pays for: a box costs a loop per box, a line one
// word operation. A line of a lower level stands for the same line at every coordinate of the
// trailing joints, so the part of a pixel's set that does not depend on them (the upper arm
// does not move with joints 3 and 4) costs only its own lines. A pixel's cells are a sequence of
// strips in ascending order of their first line; a strip is
//   its first line as the difference to the previous strip's first line (the first: to 0),
//   LEB128 (leb128.hpp);
//   its number of lines, one byte 1..255;
//   per line, one after the other, one run of joint-0 cells in it: its first cell and its
//   length (>= 1), LEB128 each - one byte each wherever joint 0 has at most 128 cells.
// Runs and strips may overlap; every cell they name is in the set.
//
// A view, like CellToPixelsTable: the arrays live in vectors or a mapped file.

#include <cstdint>
#include <memory>
#include <span>
#include <vector>

#include "safecell/cellsets/box_rows.hpp"
#include "safecell/cellsets/cell_lines.hpp"
#include "safecell/cellsets/cell_set.hpp"
#include "safecell/cellsets/leb128.hpp"
#include "safecell/cellsets/line_levels.hpp"
#include "safecell/cspace/cspace_grid.hpp"

namespace safecell {

// Cells first .. first + length - 1 of one line (counted along joint 0).
struct LineRun {
  std::uint32_t first = 0;
  std::uint32_t length = 0;
};

class PixelToCellsTable {
 public:
  PixelToCellsTable() = default;
  // Owns the arrays. offsets: pixel_count + 1 ascending byte offsets into strip_bytes (pixel =
  // row * columns + column). Throws std::invalid_argument when they do not fit together or a
  // strip is malformed or leaves the grid (every strip is decoded once here).
  PixelToCellsTable(const CspaceGrid& grid, int columns, int rows,
                    std::vector<std::uint64_t> offsets, std::vector<std::uint8_t> strip_bytes);
  PixelToCellsTable(const CspaceGrid& grid, int columns, int rows,
                    std::span<const std::uint64_t> offsets,
                    std::span<const std::uint8_t> strip_bytes, std::shared_ptr<const void> storage);

  [[nodiscard]] int columns() const { return columns_; }
  [[nodiscard]] int rows() const { return rows_; }
  [[nodiscard]] std::size_t pixel_count() const { return offsets_.size() - 1; }
  [[nodiscard]] std::uint32_t cell_count() const { return cell_count_; }
  [[nodiscard]] const BoxAxes& axes() const { return axes_; }
  [[nodiscard]] const LineLevels& levels() const { return levels_; }
  [[nodiscard]] std::uint64_t total_strips() const { return total_strips_; }

  // ORs the cells of one pixel into `cells` (precondition: pixel < pixel_count(), cells of the
  // table's grid).
  void add_cells(std::size_t pixel, CellSet& cells) const;
  // Bytes of one pixel's strips (precondition: pixel < pixel_count()).
  [[nodiscard]] std::size_t entry_bytes(std::size_t pixel) const {
    return offsets_[pixel + 1] - offsets_[pixel];
  }
  // The same into the line layout: the hot loop of fusion. Returns the number of lines written.
  std::size_t add_cells(std::size_t pixel, CellLines& cells) const {
    return cells.add_strips(strip_bytes_.data() + offsets_[pixel],
                            strip_bytes_.data() + offsets_[pixel + 1]);
  }
  // Calls visit(line, run) for every run of the pixel, line numbers of line_levels.hpp.
  template <typename Visit>
  void for_each_line_run(std::size_t pixel, Visit visit) const;
  // Calls visit(first cell, length) for every run of consecutive cells the pixel's runs stand
  // for in the full grid.
  template <typename Visit>
  void for_each_cell_run(std::size_t pixel, Visit visit) const;
  // Calls visit(cell) for every cell of the pixel, run by run (slow; for tests and baselines).
  template <typename Visit>
  void for_each_cell(std::size_t pixel, Visit visit) const;

  // Appends one strip in the coding above; `previous_first_line` is the first line of the
  // pixel's strip before it (0 for its first), first_line >= previous_first_line, 1..255 runs.
  static void append_strip(std::vector<std::uint8_t>& bytes, std::size_t previous_first_line,
                           std::size_t first_line, std::span<const LineRun> runs);

  [[nodiscard]] std::span<const std::uint64_t> offsets() const { return offsets_; }
  [[nodiscard]] std::span<const std::uint8_t> strip_bytes() const { return strip_bytes_; }
  [[nodiscard]] std::size_t bytes() const {
    return offsets_.size_bytes() + strip_bytes_.size_bytes();
  }

 private:
  void check();

  int columns_ = 0;
  int rows_ = 0;
  std::uint32_t cell_count_ = 0;
  BoxAxes axes_;
  LineLevels levels_;
  std::uint64_t total_strips_ = 0;
  std::span<const std::uint64_t> offsets_;
  std::span<const std::uint8_t> strip_bytes_;
  std::shared_ptr<const void> storage_;
};

template <typename Visit>
void PixelToCellsTable::for_each_line_run(std::size_t pixel, Visit visit) const {
  const std::uint8_t* byte = strip_bytes_.data() + offsets_[pixel];
  const std::uint8_t* const end = strip_bytes_.data() + offsets_[pixel + 1];
  std::size_t line = 0;
  while (byte != end) {
    line += read_leb128(byte);
    const std::uint32_t count = *byte++;
    for (std::uint32_t k = 0; k < count; ++k) {
      LineRun run;
      run.first = static_cast<std::uint32_t>(read_leb128(byte));
      run.length = static_cast<std::uint32_t>(read_leb128(byte));
      visit(line + k, run);
    }
  }
}

template <typename Visit>
void PixelToCellsTable::for_each_cell_run(std::size_t pixel, Visit visit) const {
  for_each_line_run(pixel, [&](std::size_t line, LineRun run) {
    const std::uint32_t level = levels_.level_of(line);
    const CellIndex copy_cells = levels_.level_cells[level];
    const auto first =
        static_cast<CellIndex>((line - levels_.first_line[level]) * levels_.line_cells + run.first);
    for (CellIndex copy = 0; copy < cell_count_; copy += copy_cells) {
      visit(copy + first, run.length);
    }
  });
}

template <typename Visit>
void PixelToCellsTable::for_each_cell(std::size_t pixel, Visit visit) const {
  for_each_cell_run(pixel, [&](CellIndex first, std::uint32_t length) {
    for (std::uint32_t i = 0; i < length; ++i) visit(first + i);
  });
}

}  // namespace safecell
