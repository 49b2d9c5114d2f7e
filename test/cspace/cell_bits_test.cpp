// The cell bit algorithms both sides use, against a dense std::vector<bool> on random ranges.

#include "safecell/cspace/cell_bits.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <vector>

#include "safecell/test/property.hpp"

namespace safecell {
namespace {

struct Dense {
  std::vector<bool> bits;
  std::uint64_t count(CellIndex begin, CellIndex end) const {
    return static_cast<std::uint64_t>(std::count(bits.begin() + begin, bits.begin() + end, true));
  }
  CellIndex next(CellIndex from, CellIndex limit, bool value) const {
    for (CellIndex c = from; c < limit; ++c) {
      if (bits[c] == value) return c;
    }
    return limit;
  }
};

TEST(CellBits, WordsHoldEveryCell) {
  EXPECT_EQ(cell_bits::words_for(0), 0u);
  EXPECT_EQ(cell_bits::words_for(1), 1u);
  EXPECT_EQ(cell_bits::words_for(64), 1u);
  EXPECT_EQ(cell_bits::words_for(65), 2u);
  EXPECT_EQ(cell_bits::words_for(0xFFFFFFFFu), 0x4000000u);
}

TEST(CellBits, RangeOperationsEqualADenseBitmap) {
  test::PropertyRun run(300);
  for (int i = 0; i < run.iterations(); ++i) {
    const auto cells = static_cast<CellIndex>(1 + run.rng()() % 700);
    std::vector<std::uint64_t> words(cell_bits::words_for(cells), 0);
    Dense dense{std::vector<bool>(cells, false)};
    for (int op = 0; op < 20; ++op) {
      CellIndex begin = static_cast<CellIndex>(run.rng()() % (cells + 1));
      CellIndex end = static_cast<CellIndex>(run.rng()() % (cells + 1));
      if (begin > end) std::swap(begin, end);
      const bool set = run.rng()() % 2 == 0;
      if (set) {
        cell_bits::set_range(words.data(), begin, end);
      } else {
        cell_bits::clear_range(words.data(), begin, end);
      }
      for (CellIndex c = begin; c < end; ++c) dense.bits[c] = set;
      const std::string input = "cells " + std::to_string(cells) + ", op " + std::to_string(op) +
                                (set ? " set [" : " clear [") + std::to_string(begin) + ", " +
                                std::to_string(end) + "), iteration " + std::to_string(i);
      ASSERT_EQ(cell_bits::count(words.data(), 0, cells), dense.count(0, cells)) << input;
      ASSERT_EQ(cell_bits::count(words.data(), begin, end), dense.count(begin, end)) << input;
      ASSERT_EQ(cell_bits::all_set(words.data(), begin, end),
                dense.count(begin, end) == end - begin)
          << input;
      const auto from = static_cast<CellIndex>(run.rng()() % (cells + 1));
      const auto limit = static_cast<CellIndex>(from + run.rng()() % (cells - from + 1));
      ASSERT_EQ(cell_bits::next_set(words.data(), from, limit), dense.next(from, limit, true))
          << input << ", from " << from << " limit " << limit;
      ASSERT_EQ(cell_bits::next_clear(words.data(), from, limit), dense.next(from, limit, false))
          << input << ", from " << from << " limit " << limit;
      // Bits past the last cell stay zero.
      const std::uint32_t tail = cells % 64;
      if (tail != 0) {
        ASSERT_EQ(words.back() >> tail, 0u) << input;
      }
    }
  }
}

TEST(CellBits, SingleCells) {
  std::uint64_t words[2] = {};
  cell_bits::set(words, 63);
  cell_bits::set(words, 64);
  EXPECT_TRUE(cell_bits::test(words, 63));
  EXPECT_TRUE(cell_bits::test(words, 64));
  EXPECT_FALSE(cell_bits::test(words, 62));
  cell_bits::clear(words, 63);
  EXPECT_FALSE(cell_bits::test(words, 63));
  EXPECT_EQ(words[0], 0u);
  EXPECT_EQ(words[1], 1u);
}

}  // namespace
}  // namespace safecell
