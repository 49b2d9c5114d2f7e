#include "safecell/lut/lut_set.hpp"

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

std::uint64_t uncompressed_bytes(std::uint64_t covered_pairs, std::uint32_t cell_count,
                                 std::size_t pixel_count) {
  return covered_pairs * (2 + 4) + std::uint64_t{cell_count} * 8 + std::uint64_t{pixel_count} * 8;
}

}  // namespace safecell
