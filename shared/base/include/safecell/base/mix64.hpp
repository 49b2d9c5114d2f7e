#pragma once
// A 64-bit mixing step (MurmurHash3's finaliser): every input bit moves about half the output
// bits. It is a bijection, so distinct inputs give distinct outputs, and only 0 maps to 0.
// Freestanding, constexpr.

#include <cstdint>

namespace safecell {

constexpr std::uint64_t mix64(std::uint64_t x) noexcept {
  x ^= x >> 33;
  x *= 0xFF51AFD7ED558CCDull;
  x ^= x >> 33;
  x *= 0xC4CEB9FE1A85EC53ull;
  x ^= x >> 33;
  return x;
}

}  // namespace safecell
