#include "safecell/base/crc32.hpp"

namespace safecell {
namespace {

struct Crc32Table {
  std::uint32_t entry[256];
};

constexpr Crc32Table make_table() {
  Crc32Table table{};
  for (std::uint32_t byte = 0; byte < 256; ++byte) {
    std::uint32_t crc = byte;
    for (int bit = 0; bit < 8; ++bit) {
      crc = (crc & 1u) != 0 ? (crc >> 1) ^ 0xEDB88320u : crc >> 1;
    }
    table.entry[byte] = crc;
  }
  return table;
}

constexpr Crc32Table kTable = make_table();
static_assert(kTable.entry[1] == 0x77073096u, "CRC-32 table disagrees with IEEE 802.3");

}  // namespace

void Crc32::update(const void* data, std::size_t size) noexcept {
  const auto* bytes = static_cast<const std::uint8_t*>(data);
  std::uint32_t crc = state_;
  for (std::size_t i = 0; i < size; ++i) {
    crc = kTable.entry[(crc ^ bytes[i]) & 0xFFu] ^ (crc >> 8);
  }
  state_ = crc;
}

std::uint32_t crc32(const void* data, std::size_t size) noexcept {
  Crc32 crc;
  crc.update(data, size);
  return crc.value();
}

}  // namespace safecell
