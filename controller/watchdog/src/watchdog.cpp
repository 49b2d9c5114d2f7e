#include "safecell/controller/watchdog.hpp"

#include "safecell/base/assert.hpp"

namespace safecell {

const char* to_string(WatchdogFault fault) noexcept {
  switch (fault) {
    case WatchdogFault::kNone:
      return "none";
    case WatchdogFault::kTooEarly:
      return "cycle too early";
    case WatchdogFault::kTooLate:
      return "cycle too late";
    case WatchdogFault::kOverrun:
      return "cycle overran its budget";
    case WatchdogFault::kFlow:
      return "cycle steps skipped or out of order";
    case WatchdogFault::kStalled:
      return "cycle stalled";
  }
  return "unknown";
}

Watchdog::Watchdog(const WatchdogConfig& config) noexcept : config_(config) {
  SAFECELL_ASSERT(config.min_period_ns > 0 && config.min_period_ns <= config.max_period_ns &&
                  config.budget_ns > 0);
}

void Watchdog::latch(WatchdogFault fault) noexcept {
  if (fault_ == WatchdogFault::kNone) fault_ = fault;  // the first cause is the one reported
}

void Watchdog::begin_cycle(std::uint64_t now_ns) noexcept {
  if (in_cycle_) flow_broken_ = true;  // the last cycle never ended
  if (started_) {
    const std::uint64_t period = now_ns >= last_begin_ns_ ? now_ns - last_begin_ns_ : 0;
    if (period < config_.min_period_ns) latch(WatchdogFault::kTooEarly);
    if (period > config_.max_period_ns) latch(WatchdogFault::kTooLate);
  }
  if (!started_) last_end_ns_ = now_ns;  // the first cycle: stalled() counts from here
  started_ = true;
  last_begin_ns_ = now_ns;
  in_cycle_ = true;
  next_step_ = 0;
}

void Watchdog::checkpoint(CycleStep step) noexcept {
  if (!in_cycle_ || static_cast<std::uint8_t>(step) != next_step_) flow_broken_ = true;
  next_step_ = static_cast<std::uint8_t>(static_cast<std::uint8_t>(step) + 1);
}

WatchdogFault Watchdog::end_cycle(std::uint64_t now_ns) noexcept {
  if (!in_cycle_ || next_step_ != kCycleSteps) flow_broken_ = true;
  if (flow_broken_) latch(WatchdogFault::kFlow);
  if (in_cycle_ && (now_ns < last_begin_ns_ || now_ns - last_begin_ns_ > config_.budget_ns)) {
    latch(WatchdogFault::kOverrun);
  }
  flow_broken_ = false;
  in_cycle_ = false;
  last_end_ns_ = now_ns;
  return fault_;
}

WatchdogFault Watchdog::stalled(std::uint64_t now_ns) noexcept {
  if (started_ && now_ns > last_end_ns_ && now_ns - last_end_ns_ > config_.max_period_ns) {
    latch(WatchdogFault::kStalled);
  }
  return fault_;
}

void Watchdog::acknowledge() noexcept {
  fault_ = WatchdogFault::kNone;
  started_ = false;
  in_cycle_ = false;
  flow_broken_ = false;
  next_step_ = 0;
}

}  // namespace safecell
