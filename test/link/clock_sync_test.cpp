// The clock offset by echo under jitter and asymmetric delay: the true offset always lies within
// the reported uncertainty, and the estimate tightens as short round trips come in.

#include "safecell/link/clock_sync.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <deque>

#include "safecell/test/property.hpp"

namespace safecell {
namespace {

constexpr std::uint64_t kUs = 1000;

TEST(ClockSync, ExactWithSymmetricDelays) {
  ClockSync sync;
  // Controller 5 s ahead; 100 us each way; the controller holds it 20 us.
  ASSERT_TRUE(sync.add({1'000'000, 5'001'000'100, 5'001'000'120, 1'000'220}));
  ASSERT_TRUE(sync.offset());
  EXPECT_EQ(sync.offset()->offset_ns, 5'000'000'000);
  EXPECT_EQ(sync.to_controller(2'000'000), 5'002'000'000u);
  EXPECT_EQ(sync.to_coprocessor(5'002'000'000), 2'000'000u);
}

TEST(ClockSync, TheTrueOffsetIsWithinTheBoundUnderJitterAndAsymmetry) {
  test::PropertyRun run(200);
  for (int i = 0; i < run.iterations(); ++i) {
    ClockSync sync(16);
    // Either clock may be ahead.
    const std::int64_t truth =
        static_cast<std::int64_t>(run.rng()() % 20'000'000'000ull) - 10'000'000'000;
    std::uint64_t t = 50'000'000'000ull;
    std::deque<std::uint64_t> window_trips;  // out + back of the samples the window keeps
    for (int echo = 0; echo < 40; ++echo) {
      // Outbound and return legs drawn independently: 50 us .. 5 ms, so up to 100x asymmetric.
      const std::uint64_t out = 50 * kUs + run.rng()() % (5000 * kUs);
      const std::uint64_t back = 50 * kUs + run.rng()() % (5000 * kUs);
      const std::uint64_t held = run.rng()() % (200 * kUs);
      const std::uint64_t t2 = t + out + static_cast<std::uint64_t>(truth);
      const EchoTimes echo_times{t, t2, t2 + held, t + out + held + back};
      ASSERT_TRUE(sync.add(echo_times));
      const ClockOffset estimate = *sync.offset();
      const std::int64_t error = estimate.offset_ns - truth;
      ASSERT_LE(static_cast<std::uint64_t>(std::llabs(error)), estimate.uncertainty_ns)
          << "truth " << truth << " ns, echo " << echo << " (out " << out << ", back " << back
          << ", held " << held << "), estimate " << estimate.offset_ns << " +- "
          << estimate.uncertainty_ns;
      t += 10'000'000;
      window_trips.push_back(out + back);
      if (window_trips.size() > 16) window_trips.pop_front();
      // The bound is the tightest the kept samples give: half the shortest round trip less the
      // time held (+1 for the halving), the older samples expired.
      ASSERT_EQ(estimate.uncertainty_ns,
                *std::min_element(window_trips.begin(), window_trips.end()) / 2 + 1)
          << "truth " << truth << " ns, echo " << echo;
    }
  }
}

TEST(ClockSync, ImpossibleSamplesAreRefused) {
  ClockSync sync;
  EXPECT_FALSE(sync.add({1000, 5000, 4000, 2000}));  // controller time runs back
  EXPECT_FALSE(sync.add({1000, 5000, 6000, 900}));   // reply before the request
  EXPECT_FALSE(sync.add({1000, 5000, 9000, 2000}));  // held longer than the whole trip
  EXPECT_FALSE(sync.offset());
  EXPECT_THROW((void)sync.to_controller(0), std::logic_error);
}

}  // namespace
}  // namespace safecell
