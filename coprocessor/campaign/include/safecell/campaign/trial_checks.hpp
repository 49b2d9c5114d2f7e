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
  [[nodiscard]] bool passed() const { return failures.empty(); }
};

TrialResult check_trial(const TrialRecord& record, const TrialBounds& bounds);

}  // namespace safecell
