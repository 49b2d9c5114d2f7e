#pragma once
// The controller core's clock: monotonic nanoseconds, the same clock the link's frame times and
// the joint samples use. Backends: CLOCK_MONOTONIC on Linux, a hardware timer on a target.
// Thread context: any; must not block or allocate.

#include <cstdint>

namespace safecell {

class ClockPort {
 public:
  ClockPort() = default;
  ClockPort(const ClockPort&) = delete;
  ClockPort& operator=(const ClockPort&) = delete;

  virtual std::uint64_t now_ns() noexcept = 0;

 protected:
  ~ClockPort() = default;
};

}  // namespace safecell
