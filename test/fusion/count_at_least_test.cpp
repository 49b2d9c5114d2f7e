#include <gtest/gtest.h>

#include <random>
#include <span>
#include <stdexcept>
#include <vector>

#include "safecell/fusion/forbidden_map_fusion.hpp"
#include "safecell/test/property.hpp"

namespace safecell {
namespace {

TEST(CountAtLeast, AgreesWithCountingCellByCell) {
  test::PropertyRun run(100);
  for (int i = 0; i < run.iterations(); ++i) {
    const auto cells = std::uniform_int_distribution<std::uint32_t>(1, 500)(run.rng());
    const auto set_count = std::uniform_int_distribution<std::size_t>(1, 6)(run.rng());
    std::vector<CellSet> sets(set_count, CellSet(cells));
    for (auto& set : sets) {
      const double density = std::uniform_real_distribution<double>(0.0, 1.0)(run.rng());
      for (CellIndex c = 0; c < cells; ++c) {
        if (std::bernoulli_distribution(density)(run.rng())) set.set(c);
      }
    }
    std::vector<std::span<const std::uint64_t>> words;
    for (const auto& set : sets) words.emplace_back(set.words());
    for (int threshold = 1; threshold <= static_cast<int>(set_count); ++threshold) {
      const std::size_t size = sets.front().words().size();
      std::vector<std::vector<std::uint64_t>> scratch(static_cast<std::size_t>(threshold),
                                                      std::vector<std::uint64_t>(size, 1));
      CellSet result(cells);
      count_at_least(words, threshold, scratch, result.words());
      for (CellIndex c = 0; c < cells; ++c) {
        int count = 0;
        for (const auto& set : sets) count += set.test(c) ? 1 : 0;
        ASSERT_EQ(result.test(c), count >= threshold) << "cell " << c << " threshold " << threshold;
      }
    }
  }
}

TEST(CountAtLeast, RefusesArraysOfOtherSizes) {
  const std::vector<std::uint64_t> three(3, 0);
  const std::vector<std::uint64_t> four(4, 0);
  std::vector<std::vector<std::uint64_t>> scratch(2, std::vector<std::uint64_t>(3, 0));
  std::vector<std::uint64_t> result(3, 0);
  EXPECT_THROW(count_at_least({three, four}, 2, scratch, result), std::invalid_argument);
  EXPECT_THROW(count_at_least({three, three}, 3, scratch, result), std::invalid_argument);
  EXPECT_THROW(count_at_least({three}, 0, scratch, result), std::invalid_argument);
  EXPECT_NO_THROW(count_at_least({three, three}, 2, scratch, result));
}

}  // namespace
}  // namespace safecell
