#pragma once
// Reflected 32-bit CRCs (initial value and final XOR 0xFFFFFFFF), table-driven, eight bytes per
// step (slicing-by-8: eight 256-entry tables, 8 KB per polynomial, read byte by byte so the result
// does not depend on the machine's byte order), the tail one byte per step:
//   Crc32        CRC-32/ISO-HDLC, polynomial 0x04C11DB7 (reflected 0xEDB88320): Ethernet, zlib,
//                PNG and the LUT files. Check value crc32("123456789") == 0xCBF43926.
//   SafetyCrc32  CRC-32/AUTOSAR, polynomial 0xF4ACFB13 (reflected 0xC8DF352F), the CRC of OPC UA
//                Safety and of the link's safety layer: Hamming distance 6 over every frame the
//                link sends (<= 1500 bytes), where the IEEE polynomial has only 4.
//                Check value safety_crc32("123456789") == 0x1697D06A.
// Real-time safe: no allocation, O(size), the tables are built at compile time.

#include <cstddef>
#include <cstdint>

namespace safecell {

template <std::uint32_t kReflectedPolynomial>
class ReflectedCrc32 {
 public:
  void update(const void* data, std::size_t size) noexcept {
    const auto* bytes = static_cast<const std::uint8_t*>(data);
    std::uint32_t crc = state_;
    const auto& t = kTables.entry;
    for (; size >= 8; size -= 8, bytes += 8) {
      const std::uint32_t low =
          crc ^ (std::uint32_t{bytes[0]} | std::uint32_t{bytes[1]} << 8 |
                 std::uint32_t{bytes[2]} << 16 | std::uint32_t{bytes[3]} << 24);
      crc = t[7][low & 0xFFu] ^ t[6][(low >> 8) & 0xFFu] ^ t[5][(low >> 16) & 0xFFu] ^
            t[4][low >> 24] ^ t[3][bytes[4]] ^ t[2][bytes[5]] ^ t[1][bytes[6]] ^ t[0][bytes[7]];
    }
    for (std::size_t i = 0; i < size; ++i) crc = t[0][(crc ^ bytes[i]) & 0xFFu] ^ (crc >> 8);
    state_ = crc;
  }
  std::uint32_t value() const noexcept { return state_ ^ 0xFFFFFFFFu; }

  static std::uint32_t of(const void* data, std::size_t size) noexcept {
    ReflectedCrc32 crc;
    crc.update(data, size);
    return crc.value();
  }

 private:
  // entry[0] is the one-byte table; entry[k][b] advances entry[k - 1][b] by one more zero byte.
  struct Tables {
    std::uint32_t entry[8][256];
  };
  static constexpr Tables make_tables() {
    Tables tables{};
    for (std::uint32_t byte = 0; byte < 256; ++byte) {
      std::uint32_t crc = byte;
      for (int bit = 0; bit < 8; ++bit) {
        crc = (crc & 1u) != 0 ? (crc >> 1) ^ kReflectedPolynomial : crc >> 1;
      }
      tables.entry[0][byte] = crc;
    }
    for (int k = 1; k < 8; ++k) {
      for (std::uint32_t byte = 0; byte < 256; ++byte) {
        const std::uint32_t previous = tables.entry[k - 1][byte];
        tables.entry[k][byte] = (previous >> 8) ^ tables.entry[0][previous & 0xFFu];
      }
    }
    return tables;
  }
  static constexpr Tables kTables = make_tables();

  std::uint32_t state_ = 0xFFFFFFFFu;
};

using Crc32 = ReflectedCrc32<0xEDB88320u>;
using SafetyCrc32 = ReflectedCrc32<0xC8DF352Fu>;

inline std::uint32_t crc32(const void* data, std::size_t size) noexcept {
  return Crc32::of(data, size);
}
inline std::uint32_t safety_crc32(const void* data, std::size_t size) noexcept {
  return SafetyCrc32::of(data, size);
}

}  // namespace safecell
