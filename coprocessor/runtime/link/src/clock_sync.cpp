#include "safecell/link/clock_sync.hpp"

#include <algorithm>
#include <stdexcept>

namespace safecell {

ClockSync::ClockSync(std::size_t window) : window_(window) {
  if (window < 1) throw std::invalid_argument("clock sync: the window must hold a sample");
}

bool ClockSync::add(const EchoTimes& echo) {
  if (echo.reply_received_ns < echo.request_sent_ns ||
      echo.reply_sent_ns < echo.request_received_ns) {
    return false;
  }
  const std::uint64_t round_trip = echo.reply_received_ns - echo.request_sent_ns;
  const std::uint64_t held = echo.reply_sent_ns - echo.request_received_ns;
  if (held > round_trip) return false;  // the controller held it longer than the whole trip
  // Signed arithmetic on differences of unsigned times; each difference fits 63 bits for any
  // two clocks within 292 years of each other.
  const auto leg_out = static_cast<std::int64_t>(echo.request_received_ns - echo.request_sent_ns);
  const auto leg_back = static_cast<std::int64_t>(echo.reply_sent_ns - echo.reply_received_ns);
  ClockOffset sample;
  sample.offset_ns = leg_out / 2 + leg_back / 2 + (leg_out % 2 + leg_back % 2) / 2;
  // +1 covers the halving's rounding.
  sample.uncertainty_ns = (round_trip - held) / 2 + 1;
  sample.round_trip_ns = round_trip;
  samples_.push_back(sample);
  while (samples_.size() > window_) samples_.pop_front();
  return true;
}

std::optional<ClockOffset> ClockSync::offset() const {
  if (samples_.empty()) return std::nullopt;
  return *std::min_element(samples_.begin(), samples_.end(),
                           [](const ClockOffset& a, const ClockOffset& b) {
                             return a.uncertainty_ns < b.uncertainty_ns;
                           });
}

std::uint64_t ClockSync::to_controller(std::uint64_t coprocessor_ns) const {
  const auto estimate = offset();
  if (!estimate) throw std::logic_error("clock sync: no echo sample yet");
  return coprocessor_ns + static_cast<std::uint64_t>(estimate->offset_ns);
}

std::uint64_t ClockSync::to_coprocessor(std::uint64_t controller_ns) const {
  const auto estimate = offset();
  if (!estimate) throw std::logic_error("clock sync: no echo sample yet");
  return controller_ns - static_cast<std::uint64_t>(estimate->offset_ns);
}

}  // namespace safecell
