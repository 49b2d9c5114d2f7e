// The cycle's watchdog: each way a cycle can go wrong latches its own fault, a good cycle none.

#include "safecell/controller/watchdog.hpp"

#include <gtest/gtest.h>

namespace safecell {
namespace {

constexpr std::uint64_t kMs = 1'000'000;

Watchdog make() { return Watchdog({3 * kMs, 5 * kMs, 1 * kMs}); }

// One cycle of every step, beginning at `at`, its work taking `work`.
WatchdogFault good_cycle(Watchdog& watchdog, std::uint64_t at, std::uint64_t work = kMs / 10) {
  watchdog.begin_cycle(at);
  for (std::uint8_t step = 0; step < kCycleSteps; ++step) {
    watchdog.checkpoint(static_cast<CycleStep>(step));
  }
  return watchdog.end_cycle(at + work);
}

TEST(Watchdog, GoodCyclesRaiseNothing) {
  Watchdog watchdog = make();
  for (std::uint64_t cycle = 0; cycle < 100; ++cycle) {
    ASSERT_EQ(good_cycle(watchdog, 10 * kMs + cycle * 4 * kMs), WatchdogFault::kNone) << cycle;
    ASSERT_EQ(watchdog.stalled(10 * kMs + cycle * 4 * kMs + 2 * kMs), WatchdogFault::kNone);
  }
}

TEST(Watchdog, TooEarly) {
  Watchdog watchdog = make();
  (void)good_cycle(watchdog, 10 * kMs);
  EXPECT_EQ(good_cycle(watchdog, 12 * kMs), WatchdogFault::kTooEarly);
}

TEST(Watchdog, TooLate) {
  Watchdog watchdog = make();
  (void)good_cycle(watchdog, 10 * kMs);
  EXPECT_EQ(good_cycle(watchdog, 16 * kMs), WatchdogFault::kTooLate);
}

TEST(Watchdog, Overrun) {
  Watchdog watchdog = make();
  EXPECT_EQ(good_cycle(watchdog, 10 * kMs, 2 * kMs), WatchdogFault::kOverrun);
}

TEST(Watchdog, StalledIsFoundFromOutside) {
  Watchdog watchdog = make();
  (void)good_cycle(watchdog, 10 * kMs);
  EXPECT_EQ(watchdog.stalled(14 * kMs), WatchdogFault::kNone);
  EXPECT_EQ(watchdog.stalled(16 * kMs), WatchdogFault::kStalled);
  EXPECT_EQ(watchdog.fault(), WatchdogFault::kStalled) << "latched";
}

TEST(Watchdog, SkippedRepeatedOrSwappedStepsBreakTheFlow) {
  const auto run = [](const std::initializer_list<CycleStep> steps) {
    Watchdog watchdog = make();
    watchdog.begin_cycle(10 * kMs);
    for (const CycleStep step : steps) watchdog.checkpoint(step);
    return watchdog.end_cycle(10 * kMs + 1000);
  };
  using S = CycleStep;
  EXPECT_EQ(run({S::kReadJoints, S::kPollLink, S::kLookAhead, S::kCommand, S::kReport}),
            WatchdogFault::kNone);
  EXPECT_EQ(run({S::kReadJoints, S::kLookAhead, S::kCommand, S::kReport}), WatchdogFault::kFlow);
  EXPECT_EQ(run({S::kReadJoints, S::kPollLink, S::kLookAhead, S::kCommand}), WatchdogFault::kFlow);
  EXPECT_EQ(
      run({S::kReadJoints, S::kPollLink, S::kPollLink, S::kLookAhead, S::kCommand, S::kReport}),
      WatchdogFault::kFlow);
  EXPECT_EQ(run({S::kPollLink, S::kReadJoints, S::kLookAhead, S::kCommand, S::kReport}),
            WatchdogFault::kFlow);
}

TEST(Watchdog, ACycleThatNeverEndedIsAFlowFault) {
  Watchdog watchdog = make();
  watchdog.begin_cycle(10 * kMs);
  watchdog.checkpoint(CycleStep::kReadJoints);
  EXPECT_EQ(good_cycle(watchdog, 14 * kMs), WatchdogFault::kFlow);
}

TEST(Watchdog, FaultsLatchUntilAcknowledged) {
  Watchdog watchdog = make();
  (void)good_cycle(watchdog, 10 * kMs);
  EXPECT_EQ(good_cycle(watchdog, 11 * kMs), WatchdogFault::kTooEarly);
  EXPECT_EQ(good_cycle(watchdog, 15 * kMs), WatchdogFault::kTooEarly) << "still latched";
  watchdog.acknowledge();
  EXPECT_EQ(good_cycle(watchdog, 40 * kMs), WatchdogFault::kNone) << "a fresh window";
  EXPECT_EQ(good_cycle(watchdog, 44 * kMs), WatchdogFault::kNone);
}

}  // namespace
}  // namespace safecell
