#include <gtest/gtest.h>

#include <random>
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
    std::vector<const CellSet*> pointers;
    for (const auto& set : sets) pointers.push_back(&set);
    for (int threshold = 1; threshold <= static_cast<int>(set_count); ++threshold) {
      std::vector<CellSet> scratch(static_cast<std::size_t>(threshold), CellSet(cells));
      CellSet result(cells);
      count_at_least(pointers, threshold, scratch, result);
      for (CellIndex c = 0; c < cells; ++c) {
        int count = 0;
        for (const auto& set : sets) count += set.test(c) ? 1 : 0;
        ASSERT_EQ(result.test(c), count >= threshold) << "cell " << c << " threshold " << threshold;
      }
    }
  }
}

}  // namespace
}  // namespace safecell
