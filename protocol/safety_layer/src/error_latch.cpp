#include "safecell/protocol/error_latch.hpp"

namespace safecell {

bool ErrorLatch::record(const LinkFault& fault, std::uint64_t now_ns) noexcept {
  if (fault.error == LinkError::kNone) return latched_;
  const auto index = static_cast<unsigned>(fault.error);
  if (index < static_cast<unsigned>(kLinkErrorCount)) ++counts_[index];
  ++total_;
  // A clock that ran back counts as within the window: when in doubt, latch.
  const bool within_window =
      have_previous_ && (now_ns < previous_ns_ || now_ns - previous_ns_ <= window_ns_);
  if (within_window && !latched_) {
    latched_ = true;
    latched_by_ = fault;
  }
  have_previous_ = true;
  previous_ns_ = now_ns;
  return latched_;
}

void ErrorLatch::acknowledge() noexcept {
  latched_ = false;
  latched_by_ = {};
  have_previous_ = false;
}

std::uint64_t ErrorLatch::count(LinkError error) const noexcept {
  const auto index = static_cast<unsigned>(error);
  return index < static_cast<unsigned>(kLinkErrorCount) ? counts_[index] : 0;
}

}  // namespace safecell
