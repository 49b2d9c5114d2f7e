#pragma once
// Session challenges for a target without a random number generator: the boot count (kept in
// non-volatile memory; the target's start-up increments and writes it back before the core
// starts) and a count of draws since boot, mixed by a bijection (base/mix64.hpp). Distinct
// (boot, draw) pairs give distinct challenges, so no challenge repeats across restarts as long as
// the boot count never does; after 2^32 - 1 draws in one boot the source is used up and no
// further session opens until a restart. The values are predictable: they guard against
// recordings replayed by the network (the black channel), not against an attacker (SECURITY.md).
// Freestanding: no allocation, no state beyond two counters.

#include <cstdint>

#include "safecell/base/mix64.hpp"
#include "safecell/controller/entropy_port.hpp"

namespace safecell {

class BootCounterEntropy final : public EntropyPort {
 public:
  // boot_count: this boot's number, 1 or more (0 is a counter never written: no challenge then).
  explicit BootCounterEntropy(std::uint32_t boot_count) noexcept : boot_count_(boot_count) {}

  bool draw(std::uint64_t& value) noexcept override {
    if (boot_count_ == 0 || draws_ == UINT32_MAX) return false;
    ++draws_;
    value = mix64((std::uint64_t{boot_count_} << 32) | draws_);
    return true;
  }

 private:
  std::uint32_t boot_count_;
  std::uint32_t draws_ = 0;
};

}  // namespace safecell
