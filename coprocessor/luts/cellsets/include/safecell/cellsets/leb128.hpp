#pragma once
// Unsigned LEB128: 7 bits a byte, low bits first, the high bit set on every byte but the last.
// Values below 128 take one byte. LUT-2 codes its line numbers and runs this way.

#include <cstdint>
#include <vector>

namespace safecell {

inline void append_leb128(std::vector<std::uint8_t>& bytes, std::uint64_t value) {
  while (value >= 0x80U) {
    bytes.push_back(static_cast<std::uint8_t>((value & 0x7FU) | 0x80U));
    value >>= 7;
  }
  bytes.push_back(static_cast<std::uint8_t>(value));
}

// Reads one value and moves `at` past it. Unchecked: for bytes checked with read_leb128_checked.
inline std::uint64_t read_leb128(const std::uint8_t*& at) {
  std::uint64_t value = 0;
  for (int shift = 0;; shift += 7) {
    const std::uint8_t byte = *at++;
    value |= std::uint64_t{byte & 0x7FU} << shift;
    if ((byte & 0x80U) == 0) return value;
  }
}

// The same, for values mostly below 128 (one byte): that case without a loop.
inline std::uint64_t read_short_leb128(const std::uint8_t*& at) {
  if (*at < 0x80U) return *at++;
  return read_leb128(at);
}

// Reads one value of at most `max_bytes` bytes before `end` in its shortest form (no trailing
// zero byte, so that a value below 128 is always one byte); false, with `at` unspecified, for
// anything else.
inline bool read_leb128_checked(const std::uint8_t*& at, const std::uint8_t* end, int max_bytes,
                                std::uint64_t& value) {
  value = 0;
  for (int index = 0; index < max_bytes && at < end; ++index) {
    const std::uint8_t byte = *at++;
    value |= std::uint64_t{byte & 0x7FU} << (7 * index);
    if ((byte & 0x80U) == 0) return index == 0 || byte != 0;
  }
  return false;
}

}  // namespace safecell
