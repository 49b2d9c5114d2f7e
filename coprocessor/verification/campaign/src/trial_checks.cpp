#include "safecell/campaign/trial_checks.hpp"

#include <algorithm>
#include <cstdio>

namespace safecell {
namespace {

double ms_between(std::uint64_t from_ns, std::uint64_t to_ns) {
  return (static_cast<double>(to_ns) - static_cast<double>(from_ns)) * 1e-6;
}

std::string fixed1(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.1f", value);
  return text;
}

void note_cause(std::vector<std::string>& causes, const std::string& cause) {
  if (cause.empty() || cause == "none") return;
  if (std::find(causes.begin(), causes.end(), cause) == causes.end()) causes.push_back(cause);
}

// Every map the controller applied against what was sent.
void check_maps(const TrialRecord& record, TrialResult& result) {
  std::string first;
  for (const ControllerTrace& trace : record.traces) {
    for (const TraceMap& map : trace.maps) {
      ++result.maps_applied;
      const auto sent = record.sent.find({map.session, map.version});
      const bool known = sent != record.sent.end();
      if (known && sent->second.hash == map.hash) continue;
      if (known && map.degraded_blocks > 0) {
        // More forbidden than was sent (the store ran out of room), so its hash differs: safe,
        // but not checked cell by cell; counted so that a campaign full of them is seen.
        ++result.degraded_maps;
        continue;
      }
      ++result.wrong_maps;
      if (first.empty()) {
        first = "version " + std::to_string(map.version) +
                (known ? " holds other cells than were sent" : " was never sent in that session");
      }
    }
  }
  if (result.wrong_maps > 0) {
    result.failures.push_back(std::to_string(result.wrong_maps) +
                              " map(s) applied that the coprocessor did not send (first: " + first +
                              ")");
  }
}

// The controller's cycles from the fault's start to the trial's end against its period.
HostLateness measure_lateness(const TrialRecord& record, const TrialBounds& bounds) {
  HostLateness host;
  host.service_behind_ms = record.service_behind_ms;
  for (const ControllerTrace& trace : record.traces) {
    const TraceCycle* before = nullptr;
    for (const TraceCycle& cycle : trace.cycles) {
      if (cycle.t_ns >= record.fault_begin_ns && cycle.t_ns <= record.end_ns && before != nullptr) {
        const double gap_ms = ms_between(before->t_ns, cycle.t_ns);
        host.controller_late_ms = std::max(host.controller_late_ms, gap_ms - bounds.period_ms);
        if (gap_ms > bounds.max_period_ms) ++host.late_cycles;
      }
      before = &cycle;
    }
  }
  return host;
}

// A failure a late host can explain, with the host's lateness beside the bound.
void timing_failed(TrialResult& result, const TrialBounds& bounds, const std::string& text) {
  result.failures.push_back(text + " [host: " + describe(result.host, bounds) + "]");
  ++result.timing_failures;
}

// Every cycle that commanded motion against the age of the data it moved on.
void check_motion_age(const TrialRecord& record, const TrialBounds& bounds, TrialResult& result) {
  for (const ControllerTrace& trace : record.traces) {
    for (const TraceCycle& cycle : trace.cycles) {
      if (!cycle.commands_motion()) continue;
      const auto sent = record.sent.find({cycle.session, cycle.map_version});
      const double age_ms = sent == record.sent.end()
                                ? bounds.moving_map_age_ms * 1e3  // on a map never sent
                                : ms_between(sent->second.exposure_ns, cycle.t_ns);
      result.worst_moving_map_age_ms = std::max(result.worst_moving_map_age_ms, age_ms);
      if (age_ms > bounds.moving_map_age_ms) ++result.stale_motion_cycles;
    }
  }
  if (result.stale_motion_cycles > 0) {
    timing_failed(result, bounds,
                  std::to_string(result.stale_motion_cycles) +
                      " cycle(s) commanded motion on data older than " +
                      fixed1(bounds.moving_map_age_ms) + " ms (worst " +
                      fixed1(result.worst_moving_map_age_ms) + " ms)");
  }
}

void collect_reactions(const TrialRecord& record, TrialResult& result) {
  const std::uint64_t causes_until = record.fault_end_ns + 1'000'000'000ull;
  for (const ControllerTrace& trace : record.traces) {
    bool moving = false;
    for (const TraceCycle& cycle : trace.cycles) {
      if (cycle.t_ns >= record.fault_begin_ns) {
        if (moving && !cycle.commands_motion()) ++result.stops;
        if (cycle.t_ns <= causes_until) {
          if (cycle.fault != "link") note_cause(result.causes, cycle.fault);
          note_cause(result.causes, cycle.link);
        }
      }
      moving = cycle.commands_motion();
    }
    std::uint64_t errors_before = 0;
    for (const TraceLinkError& error : trace.link_errors) {
      if (error.t_ns < record.fault_begin_ns) {
        errors_before = error.errors_so_far;
        continue;
      }
      result.detected += error.errors_so_far - std::min(errors_before, error.errors_so_far);
      errors_before = error.errors_so_far;
      if (error.t_ns <= causes_until) note_cause(result.causes, error.error);
    }
    std::uint64_t refused_before = 0;
    for (const TraceMapRefusal& refusal : trace.map_refusals) {
      const std::uint64_t added =
          refusal.refused_so_far - std::min(refused_before, refusal.refused_so_far);
      refused_before = refusal.refused_so_far;
      // Before the fault, and throughout a camera fault, nothing disturbs the link.
      if (refusal.t_ns < record.fault_begin_ns || site_of(record.fault) == FaultSite::kCameras) {
        result.refused_without_fault += added;
      }
      if (refusal.t_ns < record.fault_begin_ns) continue;
      result.maps_refused += added;
      if (refusal.t_ns <= causes_until) note_cause(result.causes, refusal.reason);
    }
    for (const TraceStopRequest& request : trace.stop_requests) {
      if (request.t_ns >= record.fault_begin_ns && request.t_ns <= causes_until) {
        note_cause(result.causes, request.cause);
      }
    }
  }
  if (record.refusal) note_cause(result.causes, "refused");
}

// The trace's last cycle before t_ns, if any.
const TraceCycle* last_cycle_before(const ControllerTrace& trace, std::uint64_t t_ns) {
  const TraceCycle* last = nullptr;
  for (const TraceCycle& cycle : trace.cycles) {
    if (cycle.t_ns >= t_ns) break;
    last = &cycle;
  }
  return last;
}

bool moved_before(const ControllerTrace& trace, std::uint64_t t_ns) {
  return std::any_of(trace.cycles.begin(), trace.cycles.end(), [t_ns](const TraceCycle& cycle) {
    return cycle.t_ns < t_ns && cycle.commands_motion();
  });
}

// The first cycle at or after t_ns that held the robot.
const TraceCycle* first_hold(const TrialRecord& record, std::uint64_t t_ns) {
  for (const ControllerTrace& trace : record.traces) {
    for (const TraceCycle& cycle : trace.cycles) {
      if (cycle.t_ns >= t_ns && !cycle.commands_motion()) return &cycle;
    }
  }
  return nullptr;
}

void check_stop(const TrialRecord& record, const TrialBounds& bounds, TrialResult& result) {
  const TraceCycle* hold = first_hold(record, record.fault_begin_ns);
  if (hold != nullptr) result.stop_ms = ms_between(record.fault_begin_ns, hold->t_ns);
  if (injected_at_a_rate(record.fault)) {
    if (record.injected < 2) {
      result.failures.push_back("only " + std::to_string(record.injected) +
                                " fault(s) injected, too few to latch: the trial shows nothing "
                                "(lengthen --fault-seconds or raise --rate)");
      return;
    }
    const TraceLinkError* latching = nullptr;
    for (const ControllerTrace& trace : record.traces) {
      for (const TraceLinkError& error : trace.link_errors) {
        if (error.t_ns >= record.fault_begin_ns && error.latched && latching == nullptr) {
          latching = &error;
        }
      }
    }
    if (latching == nullptr) {
      result.failures.push_back("no error latched (" + std::to_string(result.detected) +
                                " detected, " + std::to_string(result.injected) + " injected)");
      return;
    }
    const TraceCycle* held = first_hold(record, latching->t_ns);
    if (held == nullptr || ms_between(latching->t_ns, held->t_ns) > bounds.latched_stop_ms) {
      timing_failed(result, bounds,
                    "the robot was not held within " + fixed1(bounds.latched_stop_ms) +
                        " ms of the latching error");
    }
    return;
  }
  if (!result.stop_ms || *result.stop_ms > bounds.stop_ms) {
    timing_failed(
        result, bounds,
        "the robot was not held within " + fixed1(bounds.stop_ms) + " ms of the fault (" +
            (result.stop_ms ? "held after " + fixed1(*result.stop_ms) + " ms" : "never held") +
            ")");
  }
}

void check_recovery(const TrialRecord& record, const TrialBounds& bounds, TrialResult& result) {
  const ControllerTrace& last = record.traces.back();
  for (const TraceCycle& cycle : last.cycles) {
    if (cycle.t_ns >= record.fault_end_ns && cycle.commands_motion()) {
      result.recovered_s = ms_between(record.fault_end_ns, cycle.t_ns) * 1e-3;
      break;
    }
  }
  if (!result.recovered_s || *result.recovered_s > bounds.recover_s) {
    timing_failed(result, bounds,
                  "no motion again within " + fixed1(bounds.recover_s) + " s of the fault's end");
  }
}

}  // namespace

std::string describe(const HostLateness& host, const TrialBounds& bounds) {
  return "controller cycles up to " + fixed1(host.controller_late_ms) + " ms late, " +
         std::to_string(host.late_cycles) + " beyond its " + fixed1(bounds.max_period_ms) +
         " ms window; the service up to " + fixed1(host.service_behind_ms) + " ms behind";
}

TrialResult check_trial(const TrialRecord& record, const TrialBounds& bounds) {
  TrialResult result;
  result.fault = record.fault;
  result.injected = record.injected;
  if (record.traces.empty()) {
    result.failures.emplace_back("no controller trace");
    return result;
  }
  result.host = measure_lateness(record, bounds);
  check_maps(record, result);
  check_motion_age(record, bounds, result);
  collect_reactions(record, result);
  if (result.refused_without_fault > 0) {
    timing_failed(result, bounds,
                  std::to_string(result.refused_without_fault) +
                      " map update(s) refused while the link had no fault");
  }

  const std::vector<std::string>& expected = expected_causes(record.fault);
  const bool named = std::any_of(
      result.causes.begin(), result.causes.end(), [&expected](const std::string& cause) {
        return std::find(expected.begin(), expected.end(), cause) != expected.end();
      });
  if (!named) result.failures.emplace_back("the controller did not name the fault's cause");

  if (record.fault == FaultClass::kWrongFingerprint) {
    // The session is refused: the robot never moves, and there is nothing to recover.
    if (moved_before(record.traces.front(), record.end_ns + 1)) {
      result.failures.emplace_back("the robot moved without an accepted session");
    }
    return result;
  }
  // A robot already held when the fault began would pass the stop check without showing anything.
  const TraceCycle* before = last_cycle_before(record.traces.front(), record.fault_begin_ns);
  if (before == nullptr || !before->commands_motion()) {
    result.failures.emplace_back(
        "the robot was not moving when the fault began (" +
        (before == nullptr ? std::string("no cycle before it") : "state " + before->state) +
        "): the trial shows nothing");
  }
  if (record.fault == FaultClass::kControllerRestarted) {
    // The first program was killed; the second must not move before it holds a map, and every
    // map it holds must be of a session opened after the restart (it knows no older one).
    if (record.traces.size() < 2) {
      result.failures.emplace_back("no trace of the restarted controller");
    } else {
      const ControllerTrace& second = record.traces[1];
      const std::uint64_t first_map = second.maps.empty() ? UINT64_MAX : second.maps.front().t_ns;
      if (moved_before(second, first_map)) {
        result.failures.emplace_back("the restarted controller moved before it held a map");
      }
      for (const TraceMap& map : second.maps) {
        const bool old_session =
            std::any_of(record.traces.front().maps.begin(), record.traces.front().maps.end(),
                        [&map](const TraceMap& old) { return old.session == map.session; });
        if (old_session) {
          result.failures.emplace_back("the restarted controller took map version " +
                                       std::to_string(map.version) +
                                       " of the session before the restart");
          break;
        }
      }
      result.stop_ms = 0.0;  // the program's end
    }
  } else {
    check_stop(record, bounds, result);
  }
  check_recovery(record, bounds, result);
  return result;
}

}  // namespace safecell
