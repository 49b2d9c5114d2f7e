#pragma once
// The control cycle's own supervision: a windowed watchdog with a program-flow check (as
// AUTOSAR's watchdog manager does with alive and logical supervision).
//
//   flow      every cycle passes its steps in order (CycleStep); a step skipped, repeated or out
//             of order is a fault, found at the cycle's end.
//   window    cycle starts are at least min_period and at most max_period apart: too early means
//             a runaway loop, too late a stall or a missed cycle.
//   budget    a cycle's work (begin_cycle -> end_cycle) takes at most budget_ns: an overrun. The
//             safety cycle ends it at the robot's command (its report after that is I/O).
//   stalled   no cycle ended for longer than max_period: checked from outside the cycle (a timer
//             interrupt, the host module's supervisor thread, the robot's own watchdog).
// Every fault latches until acknowledge(); the cycle stops the robot (category 1) while latched.
// Thread context: begin/checkpoint/end from the cycle task; stalled() from any context (reads two
// words; on a target they are atomic). No allocation.

#include <cstdint>

namespace safecell {

enum class CycleStep : std::uint8_t {
  kReadJoints = 0,
  kPollLink,
  kLookAhead,
  kCommand,
  kReport,
};
inline constexpr std::uint8_t kCycleSteps = 5;

enum class WatchdogFault : std::uint8_t {
  kNone = 0,
  kTooEarly,  // a cycle began before min_period had passed
  kTooLate,   // a cycle began after max_period
  kOverrun,   // a cycle's work took longer than its budget
  kFlow,      // a step skipped, repeated or out of order
  kStalled,   // no cycle ended within max_period (found from outside the cycle)
};

const char* to_string(WatchdogFault fault) noexcept;

struct WatchdogConfig {
  std::uint64_t min_period_ns = 0;
  std::uint64_t max_period_ns = 0;
  std::uint64_t budget_ns = 0;
};

class Watchdog {
 public:
  // Precondition (checked): 0 < min_period <= max_period, 0 < budget.
  explicit Watchdog(const WatchdogConfig& config) noexcept;

  void begin_cycle(std::uint64_t now_ns) noexcept;
  void checkpoint(CycleStep step) noexcept;
  // The cycle's end: checks its flow and budget; returns the latched fault (kNone if none).
  WatchdogFault end_cycle(std::uint64_t now_ns) noexcept;
  // From outside the cycle: latches kStalled when the last cycle ended more than max_period ago.
  WatchdogFault stalled(std::uint64_t now_ns) noexcept;

  WatchdogFault fault() const noexcept { return fault_; }
  // Clears a latched fault; the next cycle starts a fresh window.
  void acknowledge() noexcept;
  const WatchdogConfig& config() const noexcept { return config_; }

 private:
  void latch(WatchdogFault fault) noexcept;

  WatchdogConfig config_;
  WatchdogFault fault_ = WatchdogFault::kNone;
  bool started_ = false;  // a cycle began since construction or acknowledge()
  std::uint64_t last_begin_ns_ = 0;
  std::uint64_t last_end_ns_ = 0;
  bool in_cycle_ = false;
  std::uint8_t next_step_ = 0;
  bool flow_broken_ = false;
};

}  // namespace safecell
