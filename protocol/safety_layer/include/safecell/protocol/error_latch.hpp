#pragma once
// The latch of ../shared/SAFETY.md: a second detected error within the window (default 60 min)
// latches a stop that only an explicit acknowledgement clears. Counts every error by cause for the
// status and fault reports.
// Clock: `now_ns` is the owner's own monotonic clock. Thread context: the owner's; not
// synchronised. Real-time safe: no allocation, O(1).

#include <cstdint>

#include "safecell/protocol/link_error.hpp"

namespace safecell {

inline constexpr std::uint64_t kDefaultLatchWindowNs = 60ull * 60 * 1000 * 1000 * 1000;

class ErrorLatch {
 public:
  explicit ErrorLatch(std::uint64_t window_ns = kDefaultLatchWindowNs) noexcept
      : window_ns_(window_ns) {}

  // Records a detected error (kNone is ignored). Returns latched().
  bool record(const LinkFault& fault, std::uint64_t now_ns) noexcept;

  bool latched() const noexcept { return latched_; }
  // The error that set the latch (kNone while not latched).
  const LinkFault& latched_by() const noexcept { return latched_by_; }
  // Clears the latch and forgets the errors before it; the counts stay.
  void acknowledge() noexcept;

  std::uint64_t count(LinkError error) const noexcept;
  std::uint64_t total() const noexcept { return total_; }

 private:
  std::uint64_t window_ns_;
  bool have_previous_ = false;
  std::uint64_t previous_ns_ = 0;
  bool latched_ = false;
  LinkFault latched_by_{};
  std::uint64_t counts_[kLinkErrorCount]{};
  std::uint64_t total_ = 0;
};

}  // namespace safecell
