#pragma once
// A set of C-space cells laid out for fast filling from LUT-2: every line of cells along joint 0
// (all joint-0 cells at fixed other joints) starts on a word of its own, so a run of cells in a
// line is one masked OR where joint 0 has at most 64 cells.
//
// The lines of every level (line_levels.hpp) are kept one after the other, as LUT-2 numbers them:
// a strip of a pixel writes its lines where its line numbers say, whatever their level. The lower
// levels are folded into the full grid (each line copied along the axes it spans whole) before
// the set is read: by fold(), contains() and pack_into(). CellSet (the compact layout every other
// part uses) is obtained with pack_into() or pack_lines().

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "safecell/cellsets/box_rows.hpp"
#include "safecell/cellsets/cell_set.hpp"
#include "safecell/cellsets/line_levels.hpp"

namespace safecell {

class CellLines {
 public:
  CellLines() = default;
  // Throws std::invalid_argument when the grid is not whole lines of joint 0.
  CellLines(const BoxAxes& axes, std::uint32_t cell_count);

  void clear();
  // ORs the strips of one LUT-2 entry: the bytes begin..end in the coding of
  // pixel_to_cells_table.hpp (precondition: checked, as PixelToCellsTable does when it is made,
  // and of this grid). Returns the number of lines written (its cost).
  std::size_t add_strips(const std::uint8_t* begin, const std::uint8_t* end);
  // Folds the levels into the full grid (nothing to do when no strip went below it since).
  void fold();
  // Folds the levels below `level` (1 to the full grid's) into it, no further: the set then lies
  // wholly at that level, which level_lines() reads. A set whose strips all lie at a low level (a
  // robot part moved by the first joints only) is voted on there, a fraction of the full grid.
  // Precondition: written_through() <= level (std::logic_error otherwise).
  void fold_to(std::uint32_t level);
  // The highest level a bit was written at since the set was cleared (0: none); a fold to the
  // full grid makes it the top level.
  [[nodiscard]] std::uint32_t written_through() const { return written_through_; }
  // The lines of one level, as fold_to(level) leaves them.
  [[nodiscard]] std::span<const std::uint64_t> level_lines(std::uint32_t level) const;
  // The same, for the caller to OR bits into: they stand for those lines along every axis above
  // the level once the set is folded.
  [[nodiscard]] std::span<std::uint64_t> level_lines_to_add_to(std::uint32_t level);
  // Whether the set lies wholly in the full grid (lines() may be read).
  [[nodiscard]] bool folded() const { return lowest_written_ == levels_.count; }
  // The full grid, a line after the other (throws std::logic_error when strips were added below
  // it since the last fold).
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
  [[nodiscard]] std::size_t line_count() const { return levels_.lines_of(levels_.count); }

 private:
  std::size_t add_strips_long_lines(const std::uint8_t* begin, const std::uint8_t* end);
  // Folds levels from..to-1 into `to`, zeroing them.
  void fold_levels(std::uint32_t from, std::uint32_t to);
  // Notes that `line` (the last line of an entry's strips, the highest) was written.
  void note_written_through(std::size_t line) {
    const std::uint32_t level = levels_.level_of(line);
    if (level > written_through_) written_through_ = level;
  }
  void check_level(std::uint32_t level) const;

  BoxAxes axes_;
  LineLevels levels_;
  std::uint32_t words_per_line_ = 1;  // ceil(cells along joint 0 / 64)
  // The lowest level written since the last fold (levels_.count: none below the full grid).
  std::uint32_t lowest_written_ = 0;
  // The highest level written since the set was cleared (0: none): no bit lies above it.
  std::uint32_t written_through_ = 0;
  bool clear_ = true;  // nothing added since the set was made or cleared
  std::vector<std::uint64_t> words_;
};

}  // namespace safecell
