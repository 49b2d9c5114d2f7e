#pragma once
// Reflected 32-bit CRCs (initial value and final XOR 0xFFFFFFFF), table-driven, one byte per step:
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
    for (std::size_t i = 0; i < size; ++i) {
      crc = kTable.entry[(crc ^ bytes[i]) & 0xFFu] ^ (crc >> 8);
    }
    state_ = crc;
  }
  std::uint32_t value() const noexcept { return state_ ^ 0xFFFFFFFFu; }

  static std::uint32_t of(const void* data, std::size_t size) noexcept {
    ReflectedCrc32 crc;
    crc.update(data, size);
    return crc.value();
  }

 private:
  struct Table {
    std::uint32_t entry[256];
  };
  static constexpr Table make_table() {
    Table table{};
    for (std::uint32_t byte = 0; byte < 256; ++byte) {
      std::uint32_t crc = byte;
      for (int bit = 0; bit < 8; ++bit) {
        crc = (crc & 1u) != 0 ? (crc >> 1) ^ kReflectedPolynomial : crc >> 1;
      }
      table.entry[byte] = crc;
    }
    return table;
  }
  static constexpr Table kTable = make_table();

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
