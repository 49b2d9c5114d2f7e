#pragma once
// The live status line of the coprocessor service (`safecell demo`, `safecell run`): the cycle,
// blocked feature cells per camera, forbidden cells, the controller's state, speed scale and
// critical joint, the end-to-end latency. Private to the CLI.

#include <cstdint>
#include <functional>
#include <ostream>
#include <string>
#include <unordered_map>

#include "safecell/closed_loop/closed_loop_record.hpp"
#include "safecell/service/sensing_service.hpp"

namespace safecell {

// joints: the controller's last joint state (nullptr before the first); last_latency_ms below 0
// when none is known yet.
std::string service_status_line(std::size_t index, double time_s, const ServiceCycle& cycle,
                                std::uint32_t cell_count, const JointRecord* joints,
                                double last_latency_ms);

// Where the status line goes: redrawn in place on a terminal, else one line a second (of the
// service's time). Thread context: the service's thread.
class StatusPrinter {
 public:
  explicit StatusPrinter(std::ostream& err);
  // The line for a cycle at `time_s` (seconds): `line` is called only when it will be shown.
  void cycle(double time_s, const std::function<std::string()>& line);
  // Ends the line being redrawn, if any.
  void finish();

 private:
  std::ostream& err_;
  bool interactive_;
  double next_s_ = 0.0;
};

// Exposure to the controller swapping the map in, from the joint stream: each map's exposure
// (seconds, the service's time) as it is sent, and the controller's report of the version it
// applied and when. Thread context: the service's thread.
class AppliedMapLatency {
 public:
  void sent(std::uint64_t map_version, double exposure_s) {
    exposure_of_[map_version] = exposure_s;
  }
  // A joint state after `previous` (nullptr for the first): when it names a newly applied map
  // whose exposure is known, that map's latency becomes last_ms().
  void joint_state(const JointRecord& sample, const JointRecord* previous);
  // Below 0 until one is known.
  [[nodiscard]] double last_ms() const { return last_ms_; }

 private:
  std::unordered_map<std::uint64_t, double> exposure_of_;
  double last_ms_ = -1.0;
};

}  // namespace safecell
