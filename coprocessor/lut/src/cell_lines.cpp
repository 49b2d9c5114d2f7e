#include "safecell/lut/cell_lines.hpp"

#include <algorithm>
#include <stdexcept>

namespace safecell {
namespace {

constexpr std::uint64_t kAll = ~std::uint64_t{0};

// Bits first..first+count-1 of a word (count 1..64, first + count <= 64).
std::uint64_t bit_run(std::uint32_t first, std::uint32_t count) {
  return (count == 64 ? kAll : (std::uint64_t{1} << count) - 1) << first;
}

// Calls line(index of the box's first line along axis 1) for each run of lines along axis 1,
// stepping an odometer over the box axes from 2 on.
template <typename Line>
void for_each_line_run(std::uint32_t axis_count, const std::size_t* line_stride,
                       std::size_t first_line, const std::uint8_t* extents, Line line) {
  std::uint32_t at[kMaxJoints]{};
  while (true) {
    line(first_line);
    std::uint32_t axis = 2;
    for (; axis < axis_count; ++axis) {
      if (++at[axis] < extents[axis]) {
        first_line += line_stride[axis];
        break;
      }
      first_line -= (at[axis] - 1) * line_stride[axis];
      at[axis] = 0;
    }
    if (axis >= axis_count) return;
  }
}

}  // namespace

CellLines::CellLines(const BoxAxes& axes, std::uint32_t cell_count)
    : axes_(axes), cell_count_(cell_count) {
  if (axes.count == 0 || axes.cells[0] == 0 || cell_count % axes.cells[0] != 0) {
    throw std::invalid_argument("cell lines: the grid has no joint-0 lines");
  }
  line_cells_ = axes.cells[0];
  line_divider_ = line_cells_ == 1 ? 0 : ~std::uint64_t{0} / line_cells_ + 1;
  words_per_line_ = (line_cells_ + 63) / 64;
  for (std::uint32_t axis = 1; axis < axes.count; ++axis) {
    line_stride_[axis] = axes.stride[axis] / line_cells_;
  }
  std::size_t words = 0;
  for (std::uint32_t level = 1; level <= axes.count; ++level) {
    level_lines_[level] = level < axes.count ? line_stride_[level] : cell_count / line_cells_;
    level_word_[level] = words;
    words += level_lines_[level] * words_per_line_;
  }
  words_.assign(words, 0);
  lowest_written_ = axes.count;
}

void CellLines::clear() {
  std::fill(words_.begin(), words_.end(), 0);
  lowest_written_ = axes_.count;
}

void CellLines::fold() {
  for (std::uint32_t level = lowest_written_; level < axes_.count; ++level) {
    std::uint64_t* const low = words_.data() + level_word_[level];
    std::uint64_t* up = words_.data() + level_word_[level + 1];
    const std::size_t words = level_lines_[level] * words_per_line_;
    for (std::uint32_t copy = 0; copy < axes_.cells[level]; ++copy, up += words) {
      for (std::size_t w = 0; w < words; ++w) up[w] |= low[w];
    }
    std::fill(low, low + words, 0);
  }
  lowest_written_ = axes_.count;
}

bool CellLines::contains(CellLines& other) {
  if (other.words_.size() != words_.size())
    throw std::invalid_argument("cell sets of different grids");
  fold();
  other.fold();
  std::uint64_t missing = 0;
  for (std::size_t i = level_word_[axes_.count]; i < words_.size(); ++i) {
    missing |= other.words_[i] & ~words_[i];
  }
  return missing == 0;
}

void CellLines::add_box_elsewhere(std::uint64_t* const lines, CellIndex start,
                                  const std::uint8_t* extents, std::uint32_t axes) {
  // The masks of the row inside a line: at most ceil(255 / 64) + 1 words.
  std::uint32_t word_in_line[5]{};
  std::uint64_t masks[5]{};
  std::uint32_t parts = 0;
  const LinePlace place = place_of(start);
  for (std::uint32_t cell = place.cell, left = extents[0]; left > 0; ++parts) {
    const std::uint32_t count = std::min(left, 64 - cell % 64);
    word_in_line[parts] = cell / 64;
    masks[parts] = bit_run(cell % 64, count);
    cell += count;
    left -= count;
  }
  const std::uint32_t run = axes > 1 ? extents[1] : 1;
  for_each_line_run(axes, line_stride_, place.line, extents, [&](std::size_t first_line) {
    for (std::uint32_t i = 0; i < run; ++i) {
      std::uint64_t* line = lines + (first_line + i) * words_per_line_;
      for (std::uint32_t p = 0; p < parts; ++p) line[word_in_line[p]] |= masks[p];
    }
  });
}

std::span<const std::uint64_t> CellLines::lines() const {
  if (lowest_written_ != axes_.count) throw std::logic_error("cell lines read before fold()");
  return std::span<const std::uint64_t>(words_).subspan(level_word_[axes_.count]);
}

void CellLines::pack_into(CellSet& cells) {
  fold();
  pack_lines(lines(), cells);
}

void CellLines::pack_lines(std::span<const std::uint64_t> lines, CellSet& cells) const {
  if (cells.cell_count() != cell_count_ || lines.size() != line_count() * words_per_line_) {
    throw std::invalid_argument("cell sets of different grids");
  }
  std::uint64_t* const out = cells.words().data();
  const std::uint64_t* const full = lines.data();
  cells.clear();
  for (std::size_t line = 0; line < line_count(); ++line) {
    const std::uint64_t* in = full + line * words_per_line_;
    std::size_t at = line * line_cells_;
    for (std::uint32_t word = 0, left = line_cells_; left > 0; ++word) {
      const std::uint32_t count = std::min<std::uint32_t>(left, 64);
      const std::uint64_t bits = in[word] & bit_run(0, count);
      // `bits` lands at bit `at`, over at most two words of the compact layout.
      out[at / 64] |= bits << (at % 64);
      if (at % 64 != 0 && at % 64 + count > 64) out[at / 64 + 1] |= bits >> (64 - at % 64);
      at += count;
      left -= count;
    }
  }
}

}  // namespace safecell
