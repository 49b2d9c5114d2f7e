#pragma once
// CRC-32 as in IEEE 802.3, zlib and PNG (reflected polynomial 0xEDB88320, initial value and final
// XOR 0xFFFFFFFF). Check value: crc32("123456789") == 0xCBF43926.

#include <cstddef>
#include <cstdint>

namespace safecell {

// Incremental form, for data that arrives in pieces. Real-time safe: no allocation, O(size).
class Crc32 {
 public:
  void update(const void* data, std::size_t size) noexcept;
  std::uint32_t value() const noexcept { return state_ ^ 0xFFFFFFFFu; }

 private:
  std::uint32_t state_ = 0xFFFFFFFFu;
};

std::uint32_t crc32(const void* data, std::size_t size) noexcept;

}  // namespace safecell
