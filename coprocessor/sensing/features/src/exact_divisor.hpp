#pragma once
// floor(a / d) for a fixed d > 0 without a hardware division (tens of cycles each, and the
// feature extractor needs four per cell): a multiplication with the rounded reciprocal, then
// one exact integer correction. The product is off by less than one while a / d < 2^50 and
// a < 2^62, so the corrected quotient is exact there.

#include <cstdint>

namespace safecell {

class ExactDivisor {
 public:
  explicit ExactDivisor(std::int64_t divisor)
      : divisor_(divisor), reciprocal_(1.0 / static_cast<double>(divisor)) {}

  // floor(dividend / divisor) for 0 <= dividend < 2^62.
  [[nodiscard]] std::int64_t quotient(std::int64_t dividend) const {
    const auto estimate = static_cast<std::int64_t>(static_cast<double>(dividend) * reciprocal_);
    if (estimate * divisor_ > dividend) return estimate - 1;
    if ((estimate + 1) * divisor_ <= dividend) return estimate + 1;
    return estimate;
  }

 private:
  std::int64_t divisor_;
  double reciprocal_;
};

}  // namespace safecell
