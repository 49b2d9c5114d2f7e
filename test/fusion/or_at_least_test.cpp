#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <span>
#include <stdexcept>
#include <string>
#include <vector>

#include "safecell/fusion/forbidden_map_fusion.hpp"
#include "safecell/test/property.hpp"

namespace safecell {
namespace {

// What fusion calls: the count ORed into what is there, only where the mask holds, a block of
// any size at a time; it says whether the masked count had any bit (in `into` before or not).
TEST(OrAtLeast, AddsTheMaskedCountToWhatIsThereWhateverTheBlockSize) {
  test::PropertyRun run(100);
  for (int i = 0; i < run.iterations(); ++i) {
    std::mt19937_64& rng = run.rng();
    const auto words = std::uniform_int_distribution<std::size_t>(1, 40)(rng);
    const auto set_count = std::uniform_int_distribution<std::size_t>(1, 5)(rng);
    // One more than the sets too: then no bit has enough.
    const auto threshold =
        std::uniform_int_distribution<int>(1, static_cast<int>(set_count) + 1)(rng);
    const auto block = std::uniform_int_distribution<std::size_t>(1, words + 3)(rng);
    const bool masked = std::bernoulli_distribution(0.5)(rng);
    const auto sparse = [&rng] { return rng() & rng() & rng(); };
    std::vector<std::vector<std::uint64_t>> sets(set_count, std::vector<std::uint64_t>(words));
    for (auto& set : sets) std::generate(set.begin(), set.end(), sparse);
    std::vector<std::uint64_t> mask(masked ? words : 0);
    std::generate(mask.begin(), mask.end(), [&rng] { return rng(); });
    std::vector<std::uint64_t> before(words);
    std::generate(before.begin(), before.end(), sparse);
    const std::string input =
        "words " + std::to_string(words) + ", sets " + std::to_string(set_count) + ", threshold " +
        std::to_string(threshold) + ", block " + std::to_string(block) + (masked ? ", masked" : "");

    const std::vector<std::span<const std::uint64_t>> views(sets.begin(), sets.end());
    // Scratch left over from other work: its contents must not matter.
    std::vector<std::vector<std::uint64_t>> scratch(static_cast<std::size_t>(threshold),
                                                    std::vector<std::uint64_t>(words, ~0ULL));
    std::vector<std::uint64_t> into = before;
    const bool any = or_at_least(views, threshold, mask, scratch, into, block);
    bool expected_any = false;
    for (std::size_t bit = 0; bit < words * 64; ++bit) {
      const std::size_t w = bit / 64;
      const std::uint64_t b = std::uint64_t{1} << (bit % 64);
      int count = 0;
      for (const auto& set : sets) count += (set[w] & b) != 0 ? 1 : 0;
      const bool added = count >= threshold && (!masked || (mask[w] & b) != 0);
      expected_any = expected_any || added;
      ASSERT_EQ((into[w] & b) != 0, added || (before[w] & b) != 0) << input << ", bit " << bit;
    }
    EXPECT_EQ(any, expected_any) << input;
  }
}

TEST(OrAtLeast, RefusesArraysOfOtherSizes) {
  const std::vector<std::uint64_t> three(3, 0);
  const std::vector<std::uint64_t> four(4, 0);
  std::vector<std::vector<std::uint64_t>> scratch(2, std::vector<std::uint64_t>(3, 0));
  std::vector<std::uint64_t> result(3, 0);
  EXPECT_THROW(or_at_least({three, four}, 2, {}, scratch, result), std::invalid_argument);
  EXPECT_THROW(or_at_least({three, three}, 3, {}, scratch, result), std::invalid_argument);
  EXPECT_THROW(or_at_least({three}, 0, {}, scratch, result), std::invalid_argument);
  EXPECT_NO_THROW(or_at_least({three, three}, 2, {}, scratch, result));
  EXPECT_THROW(or_at_least({three, three}, 2, four, scratch, result), std::invalid_argument);
  EXPECT_THROW(or_at_least({three, three}, 2, {}, scratch, result, 0), std::invalid_argument);
}

}  // namespace
}  // namespace safecell
