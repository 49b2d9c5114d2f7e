// The checks of a fault-campaign trial on records made up here, so that each check is seen to
// fail on the very thing it is there to catch: a map the coprocessor never sent, motion on stale
// data, a stop that comes late or never, no cause named, no recovery. A clean record passes.

#include "safecell/campaign/trial_checks.hpp"

#include <gtest/gtest.h>

#include <cstdint>

namespace safecell {
namespace {

constexpr std::uint64_t kMs = 1'000'000;
constexpr std::uint64_t kSession = 0xC0FFEE;

// A loss-free link cut from 2 s to 3.5 s, watched by a controller that does what it should: a
// map every 33 ms exposed 20 ms before it is applied, motion on each, held 250 ms after the
// last map, and moving again 300 ms after the cut ends.
struct MadeUpTrial {
  std::uint64_t cut_begin_ms = 2000;
  std::uint64_t cut_end_ms = 3500;
  std::uint64_t hold_after_ms = 250;    // from the cut's start
  std::uint64_t moving_again_ms = 300;  // from the cut's end
  FaultClass fault = FaultClass::kLinkCut;
  // The host stalls the controller for this long from stall_from_ms: no cycle then.
  std::uint64_t stall_from_ms = 0;
  std::uint64_t stall_ms = 0;

  TrialRecord record() const {
    TrialRecord record;
    record.fault = fault;
    record.fault_begin_ns = cut_begin_ms * kMs;
    record.fault_end_ns = cut_end_ms * kMs;
    record.end_ns = (cut_end_ms + 2000) * kMs;
    record.injected = 45;
    ControllerTrace trace;
    std::uint64_t version = 0;
    for (std::uint64_t t_ms = 100; t_ms * kMs < record.end_ns; t_ms += 4) {
      if (t_ms >= stall_from_ms && t_ms < stall_from_ms + stall_ms) continue;
      const bool cut = t_ms >= cut_begin_ms && t_ms < cut_end_ms;
      // A map arrives every 33 ms while the link works.
      if (!cut && t_ms % 33 < 4) {
        ++version;
        record.sent[{kSession, version}] = {(t_ms - 20) * kMs, version * 7919};
        trace.maps.push_back({t_ms * kMs, kSession, version, version * 7919, 0});
      }
      const bool held = t_ms >= cut_begin_ms + hold_after_ms && t_ms < cut_end_ms + moving_again_ms;
      TraceCycle cycle;
      cycle.t_ns = t_ms * kMs;
      cycle.state = held ? "waiting" : "moving";
      cycle.fault = "none";
      cycle.link = held ? "no map within the watchdog time" : "none";
      cycle.scale = held || version == 0 ? 0.0 : 1.0;
      cycle.map_version = version;
      cycle.session = version == 0 ? 0 : kSession;
      trace.cycles.push_back(cycle);
    }
    record.traces.push_back(trace);
    return record;
  }
};

std::string failures_of(const TrialResult& result) {
  std::string text;
  for (const std::string& failure : result.failures) text += failure + "\n";
  return text;
}

TEST(TrialChecks, AControllerThatDoesItsJobPasses) {
  const TrialResult result = check_trial(MadeUpTrial{}.record(), TrialBounds{});
  EXPECT_TRUE(result.passed()) << failures_of(result);
  EXPECT_EQ(result.wrong_maps, 0U);
  EXPECT_EQ(result.stale_motion_cycles, 0U);
  ASSERT_TRUE(result.stop_ms.has_value());
  EXPECT_NEAR(*result.stop_ms, 252.0, 4.0);
  ASSERT_TRUE(result.recovered_s.has_value());
  EXPECT_NEAR(*result.recovered_s, 0.3, 0.01);
  EXPECT_EQ(result.stops, 1U);
  EXPECT_EQ(result.causes, std::vector<std::string>{"no map within the watchdog time"});
}

TEST(TrialChecks, AMapTheCoprocessorNeverSentIsCaught) {
  TrialRecord record = MadeUpTrial{}.record();
  record.traces[0].maps[10].hash ^= 1;  // the cells the controller held were not those sent
  TrialResult result = check_trial(record, TrialBounds{});
  EXPECT_EQ(result.wrong_maps, 1U);
  EXPECT_FALSE(result.passed());

  record = MadeUpTrial{}.record();
  record.traces[0].maps[10].session ^= 1;  // a version of a session that never was
  result = check_trial(record, TrialBounds{});
  EXPECT_EQ(result.wrong_maps, 1U);

  // A store that could not hold a block exactly holds it forbidden: more than sent, not wrong.
  record = MadeUpTrial{}.record();
  record.traces[0].maps[10].hash ^= 1;
  record.traces[0].maps[10].degraded_blocks = 3;
  result = check_trial(record, TrialBounds{});
  EXPECT_EQ(result.wrong_maps, 0U) << failures_of(result);
}

TEST(TrialChecks, MotionOnStaleDataIsCaught) {
  // A controller whose watchdog is too long: it moves on through most of the cut.
  MadeUpTrial late;
  late.hold_after_ms = 1000;
  const TrialResult result = check_trial(late.record(), TrialBounds{});
  EXPECT_GT(result.stale_motion_cycles, 0U);
  EXPECT_GT(result.worst_moving_map_age_ms, TrialBounds{}.moving_map_age_ms);
  EXPECT_FALSE(result.passed());
  // ... and so its stop came late.
  EXPECT_NE(failures_of(result).find("not held within"), std::string::npos) << failures_of(result);
}

TEST(TrialChecks, AStopThatNeverComesIsCaught) {
  MadeUpTrial never;
  never.hold_after_ms = 10'000;
  never.moving_again_ms = 0;
  const TrialResult result = check_trial(never.record(), TrialBounds{});
  EXPECT_FALSE(result.stop_ms.has_value() && *result.stop_ms < 262.0);
  EXPECT_FALSE(result.passed());
}

TEST(TrialChecks, NoRecoveryIsCaught) {
  MadeUpTrial stuck;
  stuck.moving_again_ms = 5000;
  const TrialResult result = check_trial(stuck.record(), TrialBounds{});
  EXPECT_FALSE(result.recovered_s.has_value());
  EXPECT_NE(failures_of(result).find("no motion again"), std::string::npos);
}

// A stop that came late because the host stalled the controller: the failure names the host's
// lateness beside the bound and is worth one more run. The same late stop on a punctual host, and
// a wrong map on a late host, are not: they stand.
TEST(TrialChecks, ABoundBrokenOnALateHostSaysSoAndIsWorthARerun) {
  MadeUpTrial stalled;
  stalled.hold_after_ms = 400;
  stalled.stall_from_ms = 2100;
  stalled.stall_ms = 300;
  TrialResult result = check_trial(stalled.record(), TrialBounds{});
  EXPECT_FALSE(result.passed());
  EXPECT_EQ(result.timing_failures, result.failures.size()) << failures_of(result);
  EXPECT_GE(result.host.controller_late_ms, 290.0);
  EXPECT_EQ(result.host.late_cycles, 1U);
  EXPECT_TRUE(result.failed_on_a_late_host(TrialBounds{}));
  EXPECT_NE(failures_of(result).find("[host: controller cycles up to 300.0 ms late, 1 beyond"),
            std::string::npos)
      << failures_of(result);

  MadeUpTrial punctual;
  punctual.hold_after_ms = 400;
  result = check_trial(punctual.record(), TrialBounds{});
  EXPECT_FALSE(result.passed());
  EXPECT_EQ(result.host.late_cycles, 0U);
  EXPECT_FALSE(result.failed_on_a_late_host(TrialBounds{})) << "a punctual host: it stands";

  TrialRecord wrong_map = stalled.record();
  wrong_map.traces[0].maps.back().hash ^= 1U;
  result = check_trial(wrong_map, TrialBounds{});
  EXPECT_GT(result.wrong_maps, 0U);
  EXPECT_FALSE(result.failed_on_a_late_host(TrialBounds{})) << "a wrong map is never the host's";

  // The service a frame behind counts as late too.
  TrialRecord behind = punctual.record();
  behind.service_behind_ms = 40.0;
  EXPECT_TRUE(check_trial(behind, TrialBounds{}).failed_on_a_late_host(TrialBounds{}));
}

// An update refused while the link had no fault fails the trial; on a late host (its frames too
// old to be taken) it is worth one more run, on a punctual one it stands.
TEST(TrialChecks, AnUpdateRefusedOnACleanLinkFailsUnlessTheHostWasLate) {
  MadeUpTrial clean;
  TrialRecord record = clean.record();
  record.traces[0].map_refusals.push_back(
      {1000 * kMs, "delta base is not the held map", 1});  // before the fault
  TrialResult result = check_trial(record, TrialBounds{});
  EXPECT_EQ(result.refused_without_fault, 1U);
  EXPECT_NE(failures_of(result).find("refused while the link had no fault"), std::string::npos)
      << failures_of(result);
  EXPECT_FALSE(result.failed_on_a_late_host(TrialBounds{}));
  record.service_behind_ms = 40.0;
  EXPECT_TRUE(check_trial(record, TrialBounds{}).failed_on_a_late_host(TrialBounds{}));
  // The control: after the fault's start, on the link cut, a refusal is the fault's.
  record = clean.record();
  record.traces[0].map_refusals.push_back({3600 * kMs, "delta base is not the held map", 1});
  result = check_trial(record, TrialBounds{});
  EXPECT_EQ(result.refused_without_fault, 0U);
  EXPECT_TRUE(result.passed()) << failures_of(result);
}

TEST(TrialChecks, ACauseOfAnotherClassDoesNotCount) {
  MadeUpTrial other;
  other.fault = FaultClass::kCameraFrozen;  // held for "no map", never for the cameras
  const TrialResult result = check_trial(other.record(), TrialBounds{});
  EXPECT_NE(failures_of(result).find("did not name the fault's cause"), std::string::npos)
      << failures_of(result);
}

TEST(TrialChecks, AFaultAtARateMustLatch) {
  MadeUpTrial loss;
  loss.fault = FaultClass::kLoss;
  TrialRecord record = loss.record();
  // One loss detected, none latched: the robot held for another reason does not make it pass.
  record.traces[0].link_errors.push_back({2100 * kMs, "loss", false, 1});
  TrialResult result = check_trial(record, TrialBounds{});
  EXPECT_NE(failures_of(result).find("no error latched"), std::string::npos) << failures_of(result);
  // A second one latches, and the robot must be held within a cycle of it.
  record.traces[0].link_errors.push_back({2200 * kMs, "loss", true, 2});
  result = check_trial(record, TrialBounds{});
  EXPECT_NE(failures_of(result).find("latching error"), std::string::npos) << failures_of(result);
  record.traces[0].link_errors.back().t_ns = 2248 * kMs;  // 2 ms before the hold at 2250
  result = check_trial(record, TrialBounds{});
  EXPECT_TRUE(result.passed()) << failures_of(result);
  EXPECT_EQ(result.detected, 2U);
  // One fault injected cannot latch: the trial says it shows nothing, rather than pass.
  record.injected = 1;
  result = check_trial(record, TrialBounds{});
  EXPECT_NE(failures_of(result).find("too few to latch"), std::string::npos) << failures_of(result);
}

// A fault that meets a robot already held shows nothing about the stop: the trial fails.
TEST(TrialChecks, ARobotAlreadyHeldWhenTheFaultBeganFailsTheTrial) {
  TrialRecord record = MadeUpTrial{}.record();
  for (TraceCycle& cycle : record.traces[0].cycles) {
    if (cycle.t_ns + 60 * kMs >= record.fault_begin_ns && cycle.t_ns < record.fault_begin_ns) {
      cycle.scale = 0.0;
      cycle.state = "fault";
    }
  }
  const TrialResult result = check_trial(record, TrialBounds{});
  EXPECT_NE(failures_of(result).find("not moving when the fault began (state fault)"),
            std::string::npos)
      << failures_of(result);
}

// The restarted program knows no session: a map of the session before the restart that it
// holds is caught; one of a new session is not.
TEST(TrialChecks, ARestartedControllerHoldingAMapOfTheOldSessionIsCaught) {
  MadeUpTrial made_up;
  made_up.fault = FaultClass::kControllerRestarted;
  TrialRecord record = made_up.record();
  ControllerTrace second;
  second.maps.push_back({4000 * kMs, kSession, 90, 90 * 7919, 0});
  record.traces.push_back(second);
  const std::string caught = failures_of(check_trial(record, TrialBounds{}));
  EXPECT_NE(caught.find("of the session before the restart"), std::string::npos) << caught;
  record.traces[1].maps[0].session = kSession + 1;
  const std::string new_session = failures_of(check_trial(record, TrialBounds{}));
  EXPECT_EQ(new_session.find("of the session before the restart"), std::string::npos)
      << new_session;
}

TEST(TrialChecks, TheWrongFingerprintMustBeRefusedAndTheRobotNeverMove) {
  TrialRecord record;
  record.fault = FaultClass::kWrongFingerprint;
  record.refusal = "refused: LUT fingerprint differs";
  ControllerTrace trace;
  trace.cycles.push_back({10 * kMs, "waiting", "none", "no session", 0.0, 0, 0, 0.0});
  record.traces.push_back(trace);
  EXPECT_TRUE(check_trial(record, TrialBounds{}).passed());
  record.traces[0].cycles.push_back({14 * kMs, "moving", "none", "none", 1.0, 0, 0, 0.1});
  EXPECT_FALSE(check_trial(record, TrialBounds{}).passed());
  record.traces[0].cycles.pop_back();
  record.refusal.reset();
  EXPECT_FALSE(check_trial(record, TrialBounds{}).passed());
}

}  // namespace
}  // namespace safecell
