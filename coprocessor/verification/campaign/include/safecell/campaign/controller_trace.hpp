#pragma once
// A safecell-controller trace (--trace FILE, controller/host/cycle_trace.hpp) read back: its
// cycles, the maps it applied, the link errors it detected, acknowledgements and stop requests.
// Times are the controller's CLOCK_MONOTONIC ns, which on one machine is the coprocessor's
// std::chrono::steady_clock.

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace safecell {

struct TraceCycle {
  std::uint64_t t_ns = 0;
  std::string state;  // "moving", "slowed", "stopped", "waiting", "fault"
  std::string fault;  // the latched cycle fault ("none")
  std::string link;   // the link's block ("none")
  double scale = 0.0;
  std::uint64_t map_version = 0;  // the held map's (0: none)
  std::uint64_t session = 0;      // the session of the held map (0: none)
  double speed_rad_s = 0.0;       // the robot's fastest joint
  // A scale the controller could not state (written as null: not finite) counts as motion.
  [[nodiscard]] bool commands_motion() const { return !(scale <= 0.0); }
};

struct TraceMap {
  std::uint64_t t_ns = 0;
  std::uint64_t session = 0;
  std::uint64_t version = 0;
  std::uint64_t hash = 0;  // computed by the controller from the cells it holds
  std::uint32_t degraded_blocks = 0;
};

// One line per cycle in which errors were detected: the last one's name, and the count so far
// (several may fall into one cycle).
struct TraceLinkError {
  std::uint64_t t_ns = 0;
  std::string error;
  bool latched = false;
  std::uint64_t errors_so_far = 0;
};

// One line per cycle in which whole map updates were refused: the last one's reason, and the
// count so far.
struct TraceMapRefusal {
  std::uint64_t t_ns = 0;
  std::string reason;
  std::uint64_t refused_so_far = 0;
};

struct TraceStopRequest {
  std::uint64_t t_ns = 0;
  std::string cause;
};

struct ControllerTrace {
  std::vector<TraceCycle> cycles;
  std::vector<TraceMap> maps;
  std::vector<TraceLinkError> link_errors;
  std::vector<TraceMapRefusal> map_refusals;
  std::vector<std::uint64_t> acknowledged_ns;
  std::vector<TraceStopRequest> stop_requests;
};

// Reads a trace. A last line without its newline (the program killed mid-write) is left out; any
// other line that is not a trace event throws FileError naming the file, the line and what is
// wrong.
ControllerTrace read_controller_trace(const std::filesystem::path& file);

}  // namespace safecell
