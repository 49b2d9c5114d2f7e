#include "safecell/cellsets/cell_set.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <stdexcept>
#include <vector>

#include "safecell/test/property.hpp"

namespace safecell {
namespace {

TEST(CellSet, RangesAgreeWithABoolVector) {
  test::PropertyRun run(200);
  for (int i = 0; i < run.iterations(); ++i) {
    const auto count = std::uniform_int_distribution<std::uint32_t>(1, 400)(run.rng());
    CellSet set(count);
    std::vector<bool> oracle(count);
    for (int k = 0; k < 8; ++k) {
      std::uniform_int_distribution<std::uint32_t> at(0, count);
      std::uint32_t begin = at(run.rng());
      std::uint32_t end = at(run.rng());
      if (begin > end) std::swap(begin, end);
      const bool setting = k % 3 != 2;
      bool all = true;
      for (std::uint32_t c = begin; c < end; ++c) all = all && oracle[c];
      ASSERT_EQ(set.all_in_range(begin, end), all);
      if (setting) {
        set.set_range(begin, end);
      } else {
        set.reset_range(begin, end);
      }
      for (std::uint32_t c = begin; c < end; ++c) oracle[c] = setting;
    }
    std::size_t total = 0;
    CellIndex expected_next = count;
    CellIndex expected_clear = count;
    for (std::uint32_t c = count; c-- > 0;) {
      ASSERT_EQ(set.test(c), oracle[c]) << c;
      if (oracle[c]) {
        ++total;
        expected_next = c;
      } else {
        expected_clear = c;
      }
      ASSERT_EQ(set.next_set(c), oracle[c] ? c : expected_next) << c;
      ASSERT_EQ(set.next_clear(c), expected_clear) << c;
      const auto limit = std::uniform_int_distribution<std::uint32_t>(0, count + 70)(run.rng());
      ASSERT_EQ(set.next_clear(c, limit), std::min({expected_clear, limit, count}))
          << c << " before " << limit;
    }
    EXPECT_EQ(set.count(), total);
    EXPECT_EQ(set.any(), total > 0);
  }
}

TEST(CellSet, FillSetsExactlyTheCells) {
  CellSet set(130);
  set.fill();
  EXPECT_EQ(set.count(), 130U);
  EXPECT_EQ(set.next_set(129), 129U);
  set.clear();
  EXPECT_FALSE(set.any());
  EXPECT_EQ(set.next_set(0), 130U);
}

TEST(CellSet, AssignUnionIsTheUnionAndItsCount) {
  test::PropertyRun run(100);
  for (int i = 0; i < run.iterations(); ++i) {
    const auto cells = std::uniform_int_distribution<std::uint32_t>(1, 700)(run.rng());
    CellSet a(cells);
    CellSet b(cells);
    std::vector<bool> expected(cells);
    for (CellIndex c = 0; c < cells; ++c) {
      const bool in_a = std::bernoulli_distribution(0.3)(run.rng());
      const bool in_b = std::bernoulli_distribution(0.3)(run.rng());
      if (in_a) a.set(c);
      if (in_b) b.set(c);
      expected[c] = in_a || in_b;
    }
    CellSet result(cells);
    result.fill();  // whatever was there goes
    const std::size_t count = result.assign_union(a, b);
    const auto expected_count =
        static_cast<std::size_t>(std::count(expected.begin(), expected.end(), true));
    ASSERT_EQ(count, expected_count) << cells << " cells";
    for (CellIndex c = 0; c < cells; ++c) {
      ASSERT_EQ(result.test(c), expected[c]) << "cell " << c << " of " << cells;
    }
    // Into one of its own operands.
    EXPECT_EQ(a.assign_union(a, b), expected_count) << cells << " cells";
    EXPECT_EQ(a, result) << cells << " cells";
  }
  CellSet other(64);
  CellSet mine(65);
  EXPECT_THROW(mine.assign_union(mine, other), std::invalid_argument);
}

}  // namespace
}  // namespace safecell
