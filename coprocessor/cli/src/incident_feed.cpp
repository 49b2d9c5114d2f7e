#include "incident_feed.hpp"

#include <utility>

namespace safecell {

IncidentFeed::IncidentFeed(IncidentSettings settings, std::ostream& log)
    : recorder_(std::move(settings)), log_(log) {}

void IncidentFeed::joint_state(const JointRecord& sample, const JointRecord* previous) {
  recorder_.add_joint_state(
      {sample.time_s, state_name(sample.state), sample.speed_scale, sample.q, sample.velocity});
  const bool halted =
      sample.state == v1::CONTROLLER_STATE_STOPPED || sample.state == v1::CONTROLLER_STATE_FAULT;
  if (halted && (previous == nullptr || previous->state != sample.state)) {
    recorder_.trigger(sample.time_s, std::string("controller ") + state_name(sample.state));
  }
}

void IncidentFeed::cycle(double time_s, const FrameSet& frames, const ServiceCycle& cycle,
                         const CellSet& map) {
  recorder_.add_cycle(time_s, frames, cycle, map);
  const bool all_forbidden = !cycle.all_forbidden.empty();
  if (all_forbidden && !was_all_forbidden_) {
    recorder_.trigger(time_s, "all forbidden: " + cycle.all_forbidden);
  }
  was_all_forbidden_ = all_forbidden;
  report(recorder_.poll(time_s));
}

void IncidentFeed::fault(double time_s, const std::string& text) {
  recorder_.trigger(time_s, "controller fault " + text);
}

void IncidentFeed::stop_explanation(double time_s, const std::string& text) {
  recorder_.add_stop_explanation(time_s, text);
}

std::size_t IncidentFeed::finish() {
  report(recorder_.flush());
  return recorder_.incidents_written();
}

void IncidentFeed::report(const std::vector<IncidentOutcome>& outcomes) {
  for (const IncidentOutcome& outcome : outcomes) {
    if (outcome.error.empty()) {
      log_ << "incident written: " << outcome.folder.string() << '\n';
    } else {
      log_ << "incident " << outcome.error << '\n';
    }
  }
}

}  // namespace safecell
