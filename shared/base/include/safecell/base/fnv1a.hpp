#pragma once
// 64-bit FNV-1a over an explicit little-endian byte sequence, for fingerprints that must be equal
// on every platform (x86-64 coprocessor, aarch64 or Cortex-M controller).

#include <bit>
#include <cstdint>

namespace safecell {

class Fnv1a64 {
 public:
  constexpr void add_byte(std::uint8_t byte) noexcept { hash_ = (hash_ ^ byte) * 0x100000001B3ull; }
  constexpr void add_u64(std::uint64_t value) noexcept {
    for (int shift = 0; shift < 64; shift += 8) {
      add_byte(static_cast<std::uint8_t>(value >> shift));
    }
  }
  constexpr void add_u32(std::uint32_t value) noexcept {
    for (int shift = 0; shift < 32; shift += 8) {
      add_byte(static_cast<std::uint8_t>(value >> shift));
    }
  }
  // Hashes the IEEE-754 bit pattern; -0.0 is hashed as +0.0 since both mean the same quantity.
  constexpr void add_double(double value) noexcept {
    add_u64(std::bit_cast<std::uint64_t>(value == 0.0 ? 0.0 : value));
  }
  constexpr std::uint64_t value() const noexcept { return hash_; }

 private:
  std::uint64_t hash_ = 0xCBF29CE484222325ull;
};

}  // namespace safecell
