// The receiving checks of the safety layer: each communication error of IEC 61784-3 is detected
// with its cause (../shared/SAFETY.md), and the error latch.

#include "safecell/protocol/frame_checker.hpp"

#include <gtest/gtest.h>

#include <vector>

#include "safecell/protocol/error_latch.hpp"

namespace safecell {
namespace {

constexpr std::uint64_t kMs = 1'000'000;

class FrameCheckerTest : public ::testing::Test {
 protected:
  static constexpr LinkEndpoints kSender{1, 2, 0xC0FFEE, 0xF1F1};
  static constexpr LinkEndpoints kReceiver{2, 1, 0xC0FFEE, 0xF1F1};
  static constexpr ArrivalLimits kLimits{50 * kMs, 5 * kMs, 100 * kMs};

  // The next frame of the sender, captured `age` before `send`.
  std::vector<std::uint8_t> next(std::uint64_t send_ns, std::uint64_t age_ns = kMs) {
    return seal_with(sealer_, send_ns, age_ns);
  }
  static std::vector<std::uint8_t> seal_with(FrameSealer& sealer, std::uint64_t send_ns,
                                             std::uint64_t age_ns = kMs) {
    const std::uint8_t payload[4] = {1, 2, 3, 4};
    std::vector<std::uint8_t> frame(kMaxFrameBytes);
    const Result<std::size_t> size =
        sealer.seal(payload, sizeof payload, send_ns, send_ns - age_ns, frame.data(), frame.size());
    EXPECT_TRUE(size.ok());
    frame.resize(size.value_or(0));
    return frame;
  }
  Result<AcceptedFrame, LinkFault> receive(const std::vector<std::uint8_t>& frame,
                                           std::uint64_t now_ns) {
    return checker_.check(frame.data(), frame.size(), now_ns);
  }
  static void expect_refused(const Result<AcceptedFrame, LinkFault>& result, LinkError error,
                             std::uint64_t detail) {
    ASSERT_FALSE(result.ok());
    EXPECT_EQ(result.error().error, error) << to_string(result.error().error);
    EXPECT_EQ(result.error().detail, detail);
  }

  FrameSealer sealer_{kSender};
  FrameChecker checker_{kReceiver, kLimits, 0};
};

TEST_F(FrameCheckerTest, AcceptsASessionInOrder) {
  for (std::uint64_t i = 1; i <= 5; ++i) {
    const auto accepted = receive(next(10 * kMs * i), 10 * kMs * i + kMs);
    ASSERT_TRUE(accepted.ok()) << "frame " << i;
    EXPECT_EQ(accepted.value().lost, 0u);
    EXPECT_EQ(accepted.value().data_age_ns, 2 * kMs);
    EXPECT_EQ(accepted.value().frame.payload_size, 4u);
  }
  EXPECT_EQ(checker_.last_sequence(), 5u);
}

TEST_F(FrameCheckerTest, DuplicateAndReplayAreRepetitionOrIncorrectSequence) {
  const auto first = next(10 * kMs);
  const auto second = next(20 * kMs);
  ASSERT_TRUE(receive(first, 11 * kMs).ok());
  ASSERT_TRUE(receive(second, 21 * kMs).ok());
  expect_refused(receive(second, 22 * kMs), LinkError::kRepetition, 2);        // duplicate
  expect_refused(receive(first, 23 * kMs), LinkError::kIncorrectSequence, 1);  // replay
}

TEST_F(FrameCheckerTest, ReorderIsLossThenIncorrectSequence) {
  const auto first = next(10 * kMs);
  const auto second = next(20 * kMs);
  const auto third = next(30 * kMs);
  ASSERT_TRUE(receive(first, 11 * kMs).ok());
  const auto early = receive(third, 31 * kMs);
  ASSERT_TRUE(early.ok());
  EXPECT_EQ(early.value().lost, 1u);  // reported as kLoss by the owner
  expect_refused(receive(second, 32 * kMs), LinkError::kIncorrectSequence, 2);
}

TEST_F(FrameCheckerTest, LossIsCountedAndTheFrameAfterItAccepted) {
  ASSERT_TRUE(receive(next(10 * kMs), 11 * kMs).ok());
  (void)next(20 * kMs);
  (void)next(30 * kMs);
  const auto after = receive(next(40 * kMs), 41 * kMs);
  ASSERT_TRUE(after.ok());
  EXPECT_EQ(after.value().lost, 2u);
}

TEST_F(FrameCheckerTest, OldDataIsDelayAndStillMovesTheSequence) {
  expect_refused(receive(next(100 * kMs, 60 * kMs), 100 * kMs), LinkError::kDelay, 60 * kMs);
  const auto after = receive(next(110 * kMs), 111 * kMs);
  ASSERT_TRUE(after.ok());
  EXPECT_EQ(after.value().lost, 0u) << "a stale frame is not also a loss";
  // Arriving late in transit: sent fresh, but the receiver's now is far past the capture.
  expect_refused(receive(next(120 * kMs), 200 * kMs), LinkError::kDelay, 81 * kMs);
}

TEST_F(FrameCheckerTest, DataStampedInTheFutureIsDelay) {
  expect_refused(receive(next(100 * kMs), 90 * kMs), LinkError::kDelay, 9 * kMs);
  // Within the clock lead allowed for the offset's uncertainty: accepted, age 0.
  const auto within = receive(next(110 * kMs), 106 * kMs);
  ASSERT_TRUE(within.ok());
  EXPECT_EQ(within.value().data_age_ns, 0u);
}

TEST_F(FrameCheckerTest, TimeRunningBackIsIncorrectSequence) {
  ASSERT_TRUE(receive(next(50 * kMs), 51 * kMs).ok());
  expect_refused(receive(next(40 * kMs), 52 * kMs), LinkError::kIncorrectSequence, 2);
}

TEST_F(FrameCheckerTest, ForeignSessionSourceAndDestinationAreNamed) {
  FrameSealer other_session({1, 2, 0xBAD, 0xF1F1});
  expect_refused(receive(seal_with(other_session, 10 * kMs), 11 * kMs), LinkError::kMasquerade,
                 0xBAD);
  FrameSealer stranger({3, 2, 0xC0FFEE, 0xF1F1});
  expect_refused(receive(seal_with(stranger, 10 * kMs), 11 * kMs), LinkError::kInsertion, 3);
  FrameSealer misaddressed({1, 4, 0xC0FFEE, 0xF1F1});
  expect_refused(receive(seal_with(misaddressed, 10 * kMs), 11 * kMs), LinkError::kAddressing, 4);
  // None of them disturbed the session.
  ASSERT_TRUE(receive(next(20 * kMs), 21 * kMs).ok());
}

TEST_F(FrameCheckerTest, AnotherConfigurationFailsTheCrc) {
  FrameSealer reconfigured({1, 2, 0xC0FFEE, 0xF1F2});
  expect_refused(receive(seal_with(reconfigured, 10 * kMs), 11 * kMs), LinkError::kCorruption, 0);
}

TEST_F(FrameCheckerTest, TheWatchdogFiresAfterTwdWithoutAValidFrame) {
  EXPECT_EQ(checker_.watchdog(100 * kMs).error, LinkError::kNone);
  EXPECT_EQ(checker_.watchdog(101 * kMs).error, LinkError::kTimeout);
  ASSERT_TRUE(receive(next(100 * kMs), 101 * kMs).ok());
  EXPECT_EQ(checker_.watchdog(201 * kMs).error, LinkError::kNone);
  // Refused frames do not feed the watchdog.
  (void)receive(next(300 * kMs), 150 * kMs);  // stamped in the future
  const LinkFault fault = checker_.watchdog(202 * kMs);
  EXPECT_EQ(fault.error, LinkError::kTimeout);
  EXPECT_EQ(fault.detail, 101 * kMs);
}

TEST(ErrorLatch, ASecondErrorWithinTheWindowLatchesUntilAcknowledged) {
  ErrorLatch latch(60 * 1000 * kMs);
  EXPECT_FALSE(latch.record({LinkError::kLoss, 1}, 0));
  EXPECT_FALSE(latch.record({LinkError::kNone, 0}, 1 * kMs));
  EXPECT_TRUE(latch.record({LinkError::kCorruption, 0}, 59 * 1000 * kMs));
  EXPECT_EQ(latch.latched_by().error, LinkError::kCorruption);
  EXPECT_TRUE(latch.record({LinkError::kLoss, 1}, 10'000 * 1000 * kMs)) << "stays latched";
  latch.acknowledge();
  EXPECT_FALSE(latch.latched());
  EXPECT_FALSE(latch.record({LinkError::kDelay, 1}, 10'001 * 1000 * kMs));
  EXPECT_EQ(latch.count(LinkError::kLoss), 2u);
  EXPECT_EQ(latch.total(), 4u);
}

TEST(ErrorLatch, ErrorsFurtherApartThanTheWindowDoNotLatch) {
  ErrorLatch latch(60 * 1000 * kMs);
  EXPECT_FALSE(latch.record({LinkError::kLoss, 1}, 0));
  EXPECT_FALSE(latch.record({LinkError::kLoss, 1}, 61 * 1000 * kMs));
  EXPECT_FALSE(latch.record({LinkError::kLoss, 1}, 122 * 1000 * kMs));
  // A clock running back is treated as within the window.
  EXPECT_TRUE(latch.record({LinkError::kLoss, 1}, 1 * kMs));
}

TEST(LinkError, EveryErrorHasAName) {
  for (int e = 0; e < kLinkErrorCount; ++e) {
    EXPECT_STRNE(to_string(static_cast<LinkError>(e)), "unknown link error") << e;
  }
}

}  // namespace
}  // namespace safecell
