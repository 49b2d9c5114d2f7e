#pragma once
// The checks of one fault-campaign trial, on independent records: what the coprocessor sent (its
// own record of each map's session, version, exposure and hash) against what the controller's
// trace says it held and did. Nothing here takes the controller's word for whether a map was
// right: its trace hashes the cells it holds, and the coprocessor's record says what was sent.
//
//   wrong maps    a map the controller applied that the coprocessor never sent (no such session
//                 and version, or other cells). Must be 0.
//   stale motion  a cycle that commanded motion on a map whose exposure was longer ago than the
//                 safety relation allows (max data age + T_wd + a late cycle + clock lead: what
//                 ../shared/SAFETY.md lets an accepted map live). Must be 0.
//   the stop      the robot held (speed scale 0) within the bound after the fault began (after
//                 the error that latched, for faults injected at a rate).
//   the cause     the trace names one of the class's expected causes.
//   recovery      after the fault ended (and the operator acknowledged), motion again.

#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "safecell/campaign/controller_trace.hpp"
#include "safecell/campaign/fault_class.hpp"

namespace safecell {

struct SentMap {
  std::uint64_t exposure_ns = 0;  // steady clock
  std::uint64_t hash = 0;         // map_hash of the cells sent
};
// Keyed by (session id, map version).
using SentMaps = std::map<std::pair<std::uint64_t, std::uint64_t>, SentMap>;

struct TrialBounds {
  double stop_ms = 262.0;          // T_wd + a late cycle, from the fault's start
  double latched_stop_ms = 14.0;   // a late cycle and a little: from the latching error
  double moving_map_age_ms = 517;  // max data age + T_wd + a late cycle + clock lead
  double recover_s = 4.0;          // after the fault's end
  // What the host must keep to for the bounds above to mean anything: the controller's cycle
  // (its period, and the window its watchdog allows) and the service's frame period. A cycle
  // later than the window, or the service a frame or more behind, means the host was late.
  double period_ms = 4.0;
  double max_period_ms = 12.0;
  double frame_period_ms = 33.3;
};

struct TrialRecord {
  FaultClass fault = FaultClass::kLinkCut;
  std::uint64_t fault_begin_ns = 0;
  std::uint64_t fault_end_ns = 0;
  std::uint64_t end_ns = 0;
  std::vector<ControllerTrace> traces;  // one per controller program run, in order
  SentMaps sent;
  std::uint64_t injected = 0;          // faults the proxy or the cameras injected
  std::optional<std::string> refusal;  // why the controller refused the session, if it did
  // How far the service fell behind its frame schedule, at worst, from the fault's start.
  double service_behind_ms = 0.0;
};

// How late the host was while a trial was watched (from the fault's start to the trial's end).
struct HostLateness {
  double controller_late_ms = 0.0;  // the worst cycle: its gap to the one before - the period
  std::uint64_t late_cycles = 0;    // cycles later than the watchdog's window
  double service_behind_ms = 0.0;   // TrialRecord::service_behind_ms
  // Late enough that a broken time bound says more about the host than about safecell.
  [[nodiscard]] bool late(const TrialBounds& bounds) const {
    return late_cycles > 0 || service_behind_ms >= bounds.frame_period_ms;
  }
};

struct TrialResult {
  FaultClass fault = FaultClass::kLinkCut;
  std::uint64_t injected = 0;
  std::uint64_t detected = 0;      // link errors the controller logged from the fault's start
  std::uint64_t maps_refused = 0;  // whole map updates it refused from then (hash, base, ...)
  // Updates it refused while the link had no fault (before the fault, and in camera trials): a
  // failure when not 0 (MapPublisher: on a clean link every delta finds its base).
  std::uint64_t refused_without_fault = 0;
  std::uint64_t stops = 0;        // times the robot was held from the fault's start
  std::optional<double> stop_ms;  // the first hold, from the fault's start
  std::uint64_t maps_applied = 0;
  std::uint64_t wrong_maps = 0;
  std::uint64_t degraded_maps = 0;  // applied with degraded blocks: not compared by hash
  std::uint64_t stale_motion_cycles = 0;
  double worst_moving_map_age_ms = 0.0;
  std::optional<double> recovered_s;  // motion again, from the fault's end
  std::vector<std::string> causes;    // what the controller named, from the fault's start
  std::vector<std::string> failures;  // each check that failed, in words
  // Of those, the ones a late host can explain: a time bound (a stop, a recovery, the age of data
  // moved on), and updates refused on a clean link (their frames came too late to be taken).
  // Every other failure stands whatever the host did.
  std::size_t timing_failures = 0;
  HostLateness host;
  // When this is a second run: why, and what the first run found.
  std::optional<std::string> rerun_because;
  std::vector<std::string> first_run_failures;
  HostLateness first_run_host;
  [[nodiscard]] bool passed() const { return failures.empty(); }
  // Timing failures only, while the host was late: worth one more run.
  [[nodiscard]] bool failed_on_a_late_host(const TrialBounds& bounds) const {
    return !passed() && timing_failures == failures.size() && host.late(bounds);
  }
};

// One line on the host's lateness, for the table and the failure messages.
std::string describe(const HostLateness& host, const TrialBounds& bounds);

TrialResult check_trial(const TrialRecord& record, const TrialBounds& bounds);

}  // namespace safecell
