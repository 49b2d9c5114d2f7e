#include "safecell/tables/lut_set.hpp"

namespace safecell {

const char* to_string(LutSource source) {
  switch (source) {
    case LutSource::kModel:
      return "model";
    case LutSource::kRecorded:
      return "recorded";
  }
  return "unknown";
}

std::size_t PartLuts::pixel_table_bytes() const {
  std::size_t bytes = pixel_to_cells.bytes();
  for (const auto& level : pixel_blocks) bytes += level.bytes();
  for (const auto& neighbour : differences) {
    for (const auto& level : neighbour) bytes += level.bytes();
  }
  return bytes;
}

std::size_t CameraLuts::pixel_table_bytes() const {
  std::size_t bytes = 0;
  for (const auto& part : parts) bytes += part.pixel_table_bytes();
  return bytes;
}

std::uint64_t CameraLuts::covered_pairs() const {
  std::uint64_t pairs = 0;
  for (const auto& part : parts) pairs += part.covered_pairs;
  return pairs;
}

std::uint64_t uncompressed_bytes(std::uint64_t covered_pairs, std::uint32_t cell_count,
                                 std::size_t pixel_count) {
  return covered_pairs * (2 + 4) + std::uint64_t{cell_count} * 8 + std::uint64_t{pixel_count} * 8;
}

}  // namespace safecell
