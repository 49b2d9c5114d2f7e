#pragma once
// A set of C-space cells laid out for fast box filling: every line of cells along joint 0 (all
// joint-0 cells at fixed other joints) starts on a word of its own. A box of cells
// (box_rows.hpp) then sets the same bit mask in each of its lines, and its lines along box axis 1
// are neighbouring words, so fusion fills a box with a few vector operations per run of lines
// instead of a shifted range per row.
//
// A box that spans the whole range of the trailing box axes (box_cover.hpp makes many) goes into
// a level of its own: level d holds lines over the first d axes only, so such a box costs the
// lines of its leading axes. The levels are folded into the full grid (each line copied along the
// axes it spans whole) before the set is read: by contains() and pack_into(), which is why those
// are not const. CellSet (the compact layout every other part uses) is obtained with pack_into().

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "safecell/lut/box_rows.hpp"
#include "safecell/lut/cell_set.hpp"

namespace safecell {

class CellLines {
 public:
  CellLines() = default;
  CellLines(const BoxAxes& axes, std::uint32_t cell_count);

  void clear();
  // ORs the box with lowest cell `start` and one extent per box axis (precondition: the box lies
  // in the grid, as PixelToCellsTable checks when it is made).
  // Returns the number of lines written (its cost). Inline: fusion calls it once per box.
  std::size_t add_box(CellIndex start, const std::uint8_t* extents);
  // Folds the levels into the full grid (nothing to do when no box went below it since).
  void fold();
  // The full grid, a line after the other (throws std::logic_error when boxes were added below it
  // since the last fold).
  [[nodiscard]] std::span<const std::uint64_t> lines() const;
  // Whether every cell of `other` (of the same grid) is in this set.
  [[nodiscard]] bool contains(CellLines& other);
  // Writes the set into `cells` (of the same grid) in the compact layout.
  void pack_into(CellSet& cells);
  // Writes `lines` (line_count() lines of this layout, such as lines()) into `cells` in the
  // compact layout.
  void pack_lines(std::span<const std::uint64_t> lines, CellSet& cells) const;

  [[nodiscard]] std::uint32_t words_per_line() const { return words_per_line_; }
  // Lines of the full grid.
  [[nodiscard]] std::size_t line_count() const { return level_lines_[axes_.count]; }

 private:
  struct LinePlace {
    std::size_t line = 0;
    std::uint32_t cell = 0;  // along joint 0
  };
  [[nodiscard]] LinePlace place_of(CellIndex cell) const;
  // Grids of more than four box axes, or of lines longer than a word.
  void add_box_elsewhere(std::uint64_t* lines, CellIndex start, const std::uint8_t* extents,
                         std::uint32_t axes);

  BoxAxes axes_;
  std::uint32_t cell_count_ = 0;
  std::uint32_t line_cells_ = 1;  // cells along joint 0
  // ceil(2^64 / line_cells_): cell / line_cells_ is the high word of cell * line_divider_ for
  // every 32-bit cell (Lemire, Kaser & Kurz 2019), one multiplication instead of a division.
  std::uint64_t line_divider_ = 0;
  std::uint32_t words_per_line_ = 1;  // ceil(line_cells_ / 64)
  // Lines between neighbours along each box axis (axis 0 unused).
  std::size_t line_stride_[kMaxJoints]{};
  // Level d (1..axes.count) has level_lines_[d] lines from word level_word_[d] of words_;
  // level axes.count is the full grid.
  std::size_t level_lines_[kMaxJoints + 1]{};
  std::size_t level_word_[kMaxJoints + 1]{};
  // The lowest level written since the last fold (axes.count: none below the full grid).
  std::uint32_t lowest_written_ = 0;
  std::vector<std::uint64_t> words_;
};

inline CellLines::LinePlace CellLines::place_of(CellIndex cell) const {
  if (line_cells_ == 1) return {cell, 0};
  __extension__ using Wide = unsigned __int128;
  const auto line = static_cast<std::uint32_t>((static_cast<Wide>(line_divider_) * cell) >> 64);
  return {line, cell - line * line_cells_};
}

inline std::size_t CellLines::add_box(CellIndex start, const std::uint8_t* extents) {
  // The level: the box's axes up to the first of the trailing ones it spans whole. Its lowest
  // cell lies on coordinate 0 of those, so its line index is the same in the level's lines.
  std::uint32_t axes = axes_.count;
  while (axes > 1 && extents[axes - 1] == axes_.cells[axes - 1]) --axes;
  if (axes < lowest_written_) lowest_written_ = axes;
  std::uint64_t* const lines = words_.data() + level_word_[axes];
  const std::uint32_t run = axes > 1 ? extents[1] : 1;
  const std::uint32_t planes = axes > 2 ? extents[2] : 1;
  const std::uint32_t volumes = axes > 3 ? extents[3] : 1;
  if (words_per_line_ != 1 || axes > 4) {
    add_box_elsewhere(lines, start, extents, axes);
  } else {
    // The common grid (joints 1-4 discretised, joint 0 in one word): three plain loops, the
    // innermost over neighbouring words.
    const LinePlace place = place_of(start);
    const std::uint64_t mask = (extents[0] == 64 ? ~std::uint64_t{0}
                                                 : (std::uint64_t{1} << extents[0]) - 1)
                               << place.cell;
    for (std::uint32_t k3 = 0; k3 < volumes; ++k3) {
      std::uint64_t* plane = lines + place.line + k3 * line_stride_[3];
      for (std::uint32_t k2 = 0; k2 < planes; ++k2, plane += line_stride_[2]) {
        for (std::uint32_t k1 = 0; k1 < run; ++k1) plane[k1] |= mask;
      }
    }
  }
  std::size_t written = std::size_t{run} * planes * volumes;
  for (std::uint32_t axis = 4; axis < axes; ++axis) written *= extents[axis];
  return written;
}

}  // namespace safecell
