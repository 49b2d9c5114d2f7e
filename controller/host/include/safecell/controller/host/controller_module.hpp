#pragma once
// The Linux controller module: the freestanding core (map store, link, look-ahead, watchdog,
// safety cycle, planner, gross-motion service) wired to POSIX backends (a UDP socket, the
// monotonic clock) and the simulated robot, run at the configured period.
//
// The loop: sleep to the next period (absolute deadline, so the period does not drift), advance
// the simulated robot to now, ask the gross-motion service for this cycle's velocities, run the
// safety cycle, and move on through the task's goals. A latched fault holds the robot until an
// operator acknowledges it (acknowledge(), SIGUSR1 in safecell-controller).
// Thread context: run() on one thread; request_stop() and acknowledge() from any (atomics).

#include <atomic>
#include <cstdint>
#include <functional>
#include <memory>
#include <string>

#include "safecell/controller/gross_motion.hpp"
#include "safecell/controller/host/controller_config.hpp"
#include "safecell/controller/host/cycle_trace.hpp"
#include "safecell/controller/robot_port.hpp"
#include "safecell/controller/safety_cycle.hpp"

namespace safecell {

enum class TaskOutcome : std::uint8_t {
  kCompleted,  // every goal reached
  kFailed,     // a goal could not be reached (no path within give_up_s)
  kStopped,    // request_stop() (SIGINT, SIGTERM)
  kTimedOut,   // the run's duration limit passed first
};

const char* to_string(TaskOutcome outcome) noexcept;

struct ModuleStatus {
  double elapsed_s = 0.0;
  const CycleReport* cycle = nullptr;
  const MotionProgress* motion = nullptr;
  std::size_t goal = 0;  // the goal being worked on (0-based)
  std::size_t goals = 0;
  std::uint64_t cycles = 0;
  std::uint64_t overruns = 0;  // cycles that began later than one period after the last
  double worst_period_ms = 0.0;
  double worst_cycle_ms = 0.0;  // the safety cycle's own work (the watchdog's budget)
  std::string detail;           // why the task failed, when it did
  // The coprocessor's stop request, until acknowledged (whatever else holds the robot too).
  bool stop_requested = false;
  const char* stop_cause = "";  // its cause by name
};

// The module's time: the monotonic clock (a real cell), or a clock that only moves when told
// (the closed-loop validation in simulated time: lockstep_runner.hpp).
enum class ModuleTime : std::uint8_t { kMonotonic, kStepped };

class ControllerModule {
 public:
  // Throws ControllerConfigError (configuration the core refuses) or std::runtime_error (the
  // socket). Allocates everything the core uses here; nothing afterwards.
  explicit ControllerModule(const ControllerConfig& config,
                            ModuleTime time = ModuleTime::kMonotonic);
  ~ControllerModule();
  ControllerModule(const ControllerModule&) = delete;
  ControllerModule& operator=(const ControllerModule&) = delete;

  // Runs in real time until the task ends, request_stop(), or max_duration_s (0: no limit).
  // status() is called every status_period_s with the latest state. Monotonic time only.
  TaskOutcome run(double max_duration_s, double status_period_s,
                  const std::function<void(const ModuleStatus&)>& status);

  // Every cycle and link event from now on as JSON lines into `out` (cycle_trace.hpp), which must
  // outlive the module; flushed with each status and at the end of run().
  void trace_to(std::ostream& out);

  void request_stop() noexcept { stop_requested_ = true; }
  void acknowledge() noexcept { acknowledge_requested_ = true; }
  std::uint16_t listen_port() const;
  const ModuleStatus& status() const noexcept { return status_; }

  // The steps run() takes, for a driver that keeps its own time (ModuleTime::kStepped):
  // begin() once at the start time, then cycle() at each cycle's time (the robot is advanced to
  // it first), and service_link() between cycles. cycle() returns true once the run has ended
  // (outcome() says how). now_ns() is the module's clock; set_time_ns() moves a stepped clock.
  void begin(std::uint64_t start_ns);
  bool cycle(std::uint64_t now_ns);
  void service_link(std::uint64_t until_ns);
  [[nodiscard]] TaskOutcome outcome() const noexcept { return outcome_; }
  [[nodiscard]] std::uint64_t now_ns() const noexcept;
  void set_time_ns(std::uint64_t now_ns) noexcept;
  [[nodiscard]] const RobotJoints& robot_joints() const noexcept { return robot_joints_; }
  // The link's socket (to wait on it with other descriptors) and its datagram counts.
  [[nodiscard]] int socket_fd() const noexcept;
  [[nodiscard]] std::uint64_t datagrams_received() const noexcept;
  [[nodiscard]] std::uint64_t datagrams_sent() const noexcept;

 private:
  struct Parts;
  ControllerConfig config_;
  std::unique_ptr<Parts> parts_;
  ModuleStatus status_;
  TaskOutcome outcome_ = TaskOutcome::kStopped;
  RobotJoints robot_joints_{};  // the robot after the last cycle's step, before its command
  std::unique_ptr<CycleTrace> trace_;
  std::atomic<bool> stop_requested_{false};
  std::atomic<bool> acknowledge_requested_{false};
};

// One status line: time, state, speed scale, map version and age, the goal, and the reason for
// any slow-down, stop or fault.
std::string status_line(const ModuleStatus& status);

}  // namespace safecell
