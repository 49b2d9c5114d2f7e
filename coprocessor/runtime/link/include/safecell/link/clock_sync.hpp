#pragma once
// The offset between the coprocessor's clock and the controller's, by echo (paper §4.5):
//   t1  the coprocessor sends a ClockEcho (its clock)
//   t2  the controller receives it, t3 it replies (controller clock)
//   t4  the coprocessor receives the reply (its clock)
// offset = ((t2 - t1) + (t3 - t4)) / 2 is exact when both legs take equally long; whatever the
// asymmetry, the true offset lies within +-(round trip - (t3 - t2)) / 2 of it. The sample with the
// smallest round trip among the recent ones gives the tightest bound, so that one is kept.
// Offsets are controller minus coprocessor, in ns. Thread context: the link thread.

#include <cstddef>
#include <cstdint>
#include <deque>
#include <optional>

namespace safecell {

struct EchoTimes {
  std::uint64_t request_sent_ns = 0;      // t1, coprocessor clock
  std::uint64_t request_received_ns = 0;  // t2, controller clock
  std::uint64_t reply_sent_ns = 0;        // t3, controller clock
  std::uint64_t reply_received_ns = 0;    // t4, coprocessor clock
};

struct ClockOffset {
  std::int64_t offset_ns = 0;        // controller clock - coprocessor clock
  std::uint64_t uncertainty_ns = 0;  // the true offset is within offset +- uncertainty
  std::uint64_t round_trip_ns = 0;   // of the sample it comes from
};

class ClockSync {
 public:
  // Keeps the last `window` samples (drift makes old ones wrong, so they expire).
  explicit ClockSync(std::size_t window = 32);

  // False for an impossible sample (reply before request, or the controller's time running
  // back); it is not kept.
  bool add(const EchoTimes& echo);

  // Nothing until a sample was kept.
  std::optional<ClockOffset> offset() const;

  std::uint64_t to_controller(std::uint64_t coprocessor_ns) const;
  std::uint64_t to_coprocessor(std::uint64_t controller_ns) const;
  std::size_t samples() const { return samples_.size(); }

 private:
  std::size_t window_;
  std::deque<ClockOffset> samples_;
};

}  // namespace safecell
