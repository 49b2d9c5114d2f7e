#include "service_status.hpp"

#include <iostream>

#include "progress_bar.hpp"
#include "safecell/cli/text_table.hpp"

namespace safecell {

std::string service_status_line(std::size_t index, double time_s, const ServiceCycle& cycle,
                                std::uint32_t cell_count, const JointRecord* joints,
                                double last_latency_ms) {
  std::string blocked;
  for (const std::size_t count : cycle.blocked_per_camera) {
    blocked += (blocked.empty() ? "" : "/") + std::to_string(count);
  }
  std::string status = "cycle " + std::to_string(index) + "  t " + fixed(time_s, 1) +
                       " s  blocked " + (blocked.empty() ? "-" : blocked) + "  forbidden " +
                       grouped(cycle.forbidden_cells) + " (" +
                       fixed(100.0 * static_cast<double>(cycle.forbidden_cells) / cell_count, 1) +
                       " %)  " + (joints ? state_name(joints->state) : "waiting");
  if (joints) {
    status += "  scale " + fixed(joints->speed_scale, 2);
    if (joints->critical_joint > 0) status += "  joint " + std::to_string(joints->critical_joint);
  }
  status += "  latency " + (last_latency_ms >= 0.0 ? fixed(last_latency_ms, 1) + " ms" : "-");
  if (!cycle.all_forbidden.empty()) status += "  ALL FORBIDDEN: " + cycle.all_forbidden;
  if (!cycle.slowed_because.empty()) status += "  " + cycle.slowed_because;
  return status;
}

StatusPrinter::StatusPrinter(std::ostream& err)
    : err_(err), interactive_(&err == &std::cerr && ProgressBar::stderr_is_terminal()) {}

void StatusPrinter::cycle(double time_s, const std::function<std::string()>& line) {
  if (interactive_) {
    err_ << '\r' << line() << "\x1b[K" << std::flush;
  } else if (time_s >= next_s_) {
    err_ << line() << '\n';
    next_s_ = time_s + 1.0;
  }
}

void StatusPrinter::finish() {
  if (interactive_) err_ << '\n';
}

void AppliedMapLatency::joint_state(const JointRecord& sample, const JointRecord* previous) {
  if (previous != nullptr && previous->applied_map_version == sample.applied_map_version) return;
  const auto exposure = exposure_of_.find(sample.applied_map_version);
  if (exposure == exposure_of_.end()) return;
  const double applied_s =
      sample.applied_map_time_s > 0.0 ? sample.applied_map_time_s : sample.time_s;
  last_ms_ = (applied_s - exposure->second) * 1e3;
  // The maps up to this one will not be applied again: forgotten, so a long run keeps few.
  std::erase_if(exposure_of_,
                [&sample](const auto& entry) { return entry.first <= sample.applied_map_version; });
}

}  // namespace safecell
