#pragma once
// The incident recorder fed from a service loop (safecell run, the demo), with the triggers both
// share: the controller stopping or faulting (a change of state in its joint stream), a fault it
// reports, the first of a run of all-forbidden cycles. What the writer did goes to the log.
// Thread context: the service's thread. Private to the CLI.

#include <cstddef>
#include <ostream>
#include <string>

#include "safecell/closed_loop/closed_loop_record.hpp"
#include "safecell/service/incident_recorder.hpp"

namespace safecell {

class IncidentFeed {
 public:
  IncidentFeed(IncidentSettings settings, std::ostream& log);

  // A joint state of the controller's stream (times as the recorder's), after `previous`
  // (nullptr for the first).
  void joint_state(const JointRecord& sample, const JointRecord* previous);
  // A service cycle at `time_s` and the map it sent; reports the incidents written since.
  void cycle(double time_s, const FrameSet& frames, const ServiceCycle& cycle, const CellSet& map);
  // A fault the controller reported.
  void fault(double time_s, const std::string& text);
  // Why the controller slowed down or stopped (the service's stop explanation).
  void stop_explanation(double time_s, const std::string& text);
  // The end of the run: the incident being recorded is written; returns the incidents written.
  std::size_t finish();
  // Incidents that could not be written (finish() first).
  [[nodiscard]] std::size_t not_written() const { return recorder_.incidents_not_written(); }

 private:
  void report(const std::vector<IncidentOutcome>& outcomes);

  IncidentRecorder recorder_;
  std::ostream& log_;
  bool was_all_forbidden_ = false;
};

}  // namespace safecell
