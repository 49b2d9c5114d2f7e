#pragma once
// Seeded property tests. The seed and the iteration count come from the command line
// (--seed=N, --iterations=N) or the environment (SAFECELL_SEED, SAFECELL_ITERATIONS); without
// them the seed is random. Every failure message carries the seed that reproduces it.

#include <gtest/gtest.h>

#include <cstdint>
#include <random>
#include <stdexcept>

namespace safecell::test {

// Thrown by the test runner's SAFECELL_ASSERT handler.
class AssertFailure : public std::logic_error {
 public:
  using std::logic_error::logic_error;
};

struct PropertySettings {
  std::uint64_t seed = 0;
  int iterations = 0;  // 0: the test's own default
};

// Set once by main().
PropertySettings& property_settings();

class PropertyRun {
 public:
  explicit PropertyRun(int default_iterations);
  std::uint64_t seed() const { return seed_; }
  int iterations() const { return iterations_; }
  // Whether the run is at least as long as the test's default. A test's coverage floors (enough
  // random inputs reached the case it is about) are set for its default count; a short run that
  // replays one failure (--iterations=1) skips them.
  bool full_length() const { return iterations_ >= default_iterations_; }
  std::mt19937_64& rng() { return rng_; }

 private:
  std::uint64_t seed_;
  int default_iterations_;
  int iterations_;
  std::mt19937_64 rng_;
  ::testing::ScopedTrace trace_;
};

}  // namespace safecell::test
