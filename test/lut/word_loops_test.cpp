#include "safecell/compute/word_loops.hpp"

#include <gtest/gtest.h>

#include <random>
#include <vector>

#include "safecell/test/property.hpp"

namespace safecell {
namespace {

std::vector<std::uint64_t> random_words(std::mt19937_64& rng, std::size_t count) {
  std::vector<std::uint64_t> words(count);
  for (auto& word : words) word = rng() & rng();  // about a quarter of the bits
  return words;
}

TEST(WordLoops, AgreeWithWordByWord) {
  test::PropertyRun run(200);
  for (int i = 0; i < run.iterations(); ++i) {
    // Lengths around the block of four and well past it.
    const auto count = std::uniform_int_distribution<std::size_t>(0, 23)(run.rng());
    const auto to = random_words(run.rng(), count);
    const auto a = random_words(run.rng(), count);
    const auto b = random_words(run.rng(), count);
    std::vector<std::uint64_t> ored = to;
    std::vector<std::uint64_t> or_anded = to;
    or_words(ored.data(), a.data(), count);
    or_and_words(or_anded.data(), a.data(), b.data(), count);
    bool missing = false;
    for (std::size_t w = 0; w < count; ++w) {
      ASSERT_EQ(ored[w], to[w] | a[w]);
      ASSERT_EQ(or_anded[w], to[w] | (a[w] & b[w]));
      missing = missing || (b[w] & ~a[w]) != 0;
    }
    EXPECT_EQ(any_missing(a.data(), b.data(), count), missing);
    EXPECT_FALSE(any_missing(ored.data(), a.data(), count));
  }
}

}  // namespace
}  // namespace safecell
