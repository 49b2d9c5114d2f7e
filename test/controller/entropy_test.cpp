// The sources of session challenges: fresh across draws and across boots, and a source that
// cannot be fresh says so instead of giving a value.

#include <gtest/gtest.h>

#include <cstdint>
#include <set>

#include "safecell/controller/boot_counter_entropy.hpp"
#include "safecell/controller/host/system_entropy.hpp"

namespace safecell {
namespace {

TEST(BootCounterEntropy, NoChallengeRepeatsWithinABootOrAcrossBoots) {
  std::set<std::uint64_t> seen;
  for (std::uint32_t boot = 1; boot <= 50; ++boot) {
    BootCounterEntropy entropy(boot);
    for (int draw = 0; draw < 200; ++draw) {
      std::uint64_t value = 0;
      ASSERT_TRUE(entropy.draw(value));
      EXPECT_NE(value, 0u);
      EXPECT_TRUE(seen.insert(value).second) << "boot " << boot << ", draw " << draw;
    }
  }
  // The control: a boot counter that was not kept (the same count again) repeats the challenges.
  BootCounterEntropy again(1);
  std::uint64_t first = 0;
  ASSERT_TRUE(again.draw(first));
  EXPECT_EQ(seen.count(first), 1u);
}

TEST(BootCounterEntropy, ACounterNeverWrittenGivesNoChallenge) {
  BootCounterEntropy unwritten(0);
  std::uint64_t value = 7;
  EXPECT_FALSE(unwritten.draw(value));
  EXPECT_EQ(value, 7u);
}

TEST(SystemEntropy, DrawsDiffer) {
  SystemEntropy entropy;
  std::set<std::uint64_t> seen;
  for (int draw = 0; draw < 100; ++draw) {
    std::uint64_t value = 0;
    ASSERT_TRUE(entropy.draw(value));
    seen.insert(value);
  }
  EXPECT_EQ(seen.size(), 100u);
}

}  // namespace
}  // namespace safecell
