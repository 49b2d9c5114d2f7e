#include "safecell/cellsets/cell_lines.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>

#include "safecell/cellsets/leb128.hpp"
#include "safecell/compute/word_loops.hpp"

namespace safecell {
namespace {

constexpr std::uint64_t kAll = ~std::uint64_t{0};

// Bits first..first+count-1 of a word (count 1..64, first + count <= 64).
std::uint64_t bit_run(std::uint32_t first, std::uint32_t count) {
  return (kAll >> (64 - count)) << first;
}

// Appends runs of bits to an array of words, writing each word once as it fills.
struct BitAppender {
  std::uint64_t* out;
  std::uint64_t word = 0;
  std::uint32_t filled = 0;  // bits of `word` taken, below 64

  // Appends the low `count` bits of `bits` (count 1..64; the bits above it zero).
  void append(std::uint64_t bits, std::uint32_t count) {
    word |= bits << filled;
    filled += count;
    if (filled < 64) return;
    *out++ = word;
    filled -= 64;
    // The top `filled` bits of `bits` did not fit.
    word = filled == 0 ? 0 : bits >> (count - filled);
  }
  // Writes the last word, when it holds any bits.
  void finish() const {
    if (filled != 0) *out = word;
  }
};

}  // namespace

CellLines::CellLines(const BoxAxes& axes, std::uint32_t cell_count)
    : axes_(axes), levels_(LineLevels::of(axes, cell_count)) {
  words_per_line_ = (levels_.line_cells + 63) / 64;
  words_.assign(levels_.total_lines() * words_per_line_, 0);
  lowest_written_ = levels_.count;
}

void CellLines::clear() {
  // A set nothing was added to since it was cleared is clear: fusion clears every part's set of
  // every camera each cycle, most of them untouched, and on a fine grid each is megabytes. No bit
  // lies above written_through_: a set of a part moved by the first joints only, voted on at its
  // level, clears that much.
  if (!clear_ && written_through_ > 0) {
    std::fill_n(
        words_.begin(),
        static_cast<std::ptrdiff_t>(levels_.first_line[written_through_ + 1] * words_per_line_), 0);
  }
  clear_ = true;
  lowest_written_ = levels_.count;
  written_through_ = 0;
}

std::size_t CellLines::add_strips(const std::uint8_t* begin, const std::uint8_t* end) {
  if (begin == end) return 0;
  clear_ = false;
  if (words_per_line_ != 1) return add_strips_long_lines(begin, end);
  // Strips come in ascending line order: the first holds the entry's lowest line.
  const std::uint8_t* at = begin;
  std::size_t line = read_leb128(at);
  lowest_written_ = std::min(lowest_written_, levels_.level_of(line));
  std::uint64_t* const words = words_.data();
  std::size_t written = 0;
  while (true) {
    const std::uint32_t count = *at++;
    std::uint64_t* const strip = words + line;
    // Joint 0 fits a word, so every run's first cell and length are below 128: one byte each.
    for (std::uint32_t k = 0; k < count; ++k, at += 2) strip[k] |= bit_run(at[0], at[1]);
    written += count;
    if (at == end) {
      note_written_through(line + count - 1);
      return written;
    }
    line += read_leb128(at);
  }
}

std::size_t CellLines::add_strips_long_lines(const std::uint8_t* begin, const std::uint8_t* end) {
  const std::uint8_t* at = begin;
  std::size_t line = read_leb128(at);
  lowest_written_ = std::min(lowest_written_, levels_.level_of(line));
  std::size_t written = 0;
  while (true) {
    const std::uint32_t count = *at++;
    for (std::uint32_t k = 0; k < count; ++k) {
      const auto cell = static_cast<std::uint32_t>(read_short_leb128(at));
      const auto last = cell + static_cast<std::uint32_t>(read_short_leb128(at)) - 1;
      std::uint64_t* const words = words_.data() + (line + k) * words_per_line_;
      const std::uint32_t first_word = cell / 64;
      const std::uint32_t last_word = last / 64;
      const std::uint64_t from_first = kAll << (cell % 64);
      const std::uint64_t to_last = kAll >> (63 - last % 64);
      if (first_word == last_word) {
        words[first_word] |= from_first & to_last;
        continue;
      }
      // The words between are wholly in the run: written, not read.
      words[first_word] |= from_first;
      for (std::uint32_t w = first_word + 1; w < last_word; ++w) words[w] = kAll;
      words[last_word] |= to_last;
    }
    written += count;
    if (at == end) {
      note_written_through(line + count - 1);
      return written;
    }
    line += read_leb128(at);
  }
}

void CellLines::fold_levels(std::uint32_t from, std::uint32_t to) {
  for (std::uint32_t level = from; level < to; ++level) {
    std::uint64_t* const low = words_.data() + levels_.first_line[level] * words_per_line_;
    std::uint64_t* up = words_.data() + levels_.first_line[level + 1] * words_per_line_;
    const std::size_t words = levels_.lines_of(level) * words_per_line_;
    for (std::uint32_t copy = 0; copy < axes_.cells[level]; ++copy, up += words) {
      or_words(up, low, words);
    }
    std::fill(low, low + words, 0);
  }
}

void CellLines::fold() {
  if (lowest_written_ == levels_.count) return;
  fold_levels(lowest_written_, levels_.count);
  lowest_written_ = levels_.count;
  written_through_ = levels_.count;
}

void CellLines::check_level(std::uint32_t level) const {
  if (level < 1 || level > levels_.count) {
    throw std::invalid_argument("cell lines: level " + std::to_string(level) + " of 1.." +
                                std::to_string(levels_.count));
  }
}

void CellLines::fold_to(std::uint32_t level) {
  check_level(level);
  if (written_through_ > level) {
    throw std::logic_error("cell lines: folding to level " + std::to_string(level) +
                           ", below bits written at level " + std::to_string(written_through_));
  }
  // Nothing below the level: the set is empty, or lies at the level already.
  if (lowest_written_ >= level) return;
  fold_levels(lowest_written_, level);
  lowest_written_ = level;
  written_through_ = level;  // the bits below it moved up to it
}

std::span<const std::uint64_t> CellLines::level_lines(std::uint32_t level) const {
  check_level(level);
  return std::span<const std::uint64_t>(words_).subspan(levels_.first_line[level] * words_per_line_,
                                                        levels_.lines_of(level) * words_per_line_);
}

std::span<std::uint64_t> CellLines::level_lines_to_add_to(std::uint32_t level) {
  check_level(level);
  clear_ = false;
  lowest_written_ = std::min(lowest_written_, level);
  written_through_ = std::max(written_through_, level);
  return std::span<std::uint64_t>(words_).subspan(levels_.first_line[level] * words_per_line_,
                                                  levels_.lines_of(level) * words_per_line_);
}

std::span<const std::uint64_t> CellLines::lines() const {
  if (lowest_written_ != levels_.count) throw std::logic_error("cell lines read before fold()");
  return std::span<const std::uint64_t>(words_).subspan(levels_.first_line[levels_.count] *
                                                        words_per_line_);
}

bool CellLines::contains(CellLines& other) {
  if (other.words_.size() != words_.size())
    throw std::invalid_argument("cell sets of different grids");
  fold();
  other.fold();
  const std::span<const std::uint64_t> mine = lines();
  const std::span<const std::uint64_t> theirs = other.lines();
  return !any_missing(mine.data(), theirs.data(), mine.size());
}

void CellLines::pack_into(CellSet& cells) {
  fold();
  pack_lines(lines(), cells);
}

void CellLines::pack_lines(std::span<const std::uint64_t> lines, CellSet& cells) const {
  if (cells.cell_count() != levels_.cell_count || lines.size() != line_count() * words_per_line_) {
    throw std::invalid_argument("cell sets of different grids");
  }
  // Each line's bits are appended to a word that is written out whenever it fills: every word
  // of `cells` is written once, none is read.
  BitAppender packed{cells.words().data()};
  const std::uint32_t line_cells = levels_.line_cells;
  if (words_per_line_ == 1) {
    const std::uint64_t line_bits = bit_run(0, line_cells);
    for (std::size_t line = 0; line < line_count(); ++line) {
      packed.append(lines[line] & line_bits, line_cells);
    }
  } else {
    for (std::size_t line = 0; line < line_count(); ++line) {
      const std::uint64_t* in = lines.data() + line * words_per_line_;
      for (std::uint32_t word = 0, left = line_cells; left > 0; ++word) {
        const std::uint32_t count = std::min<std::uint32_t>(left, 64);
        packed.append(in[word] & bit_run(0, count), count);
        left -= count;
      }
    }
  }
  packed.finish();
}

}  // namespace safecell
