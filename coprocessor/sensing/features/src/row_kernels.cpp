#include "row_kernels.hpp"

#include <algorithm>

// Each kernel twice on x86-64: for the baseline (SSE2) and for AVX2, chosen once when the
// program loads (GCC and Clang function multi-versioning); elsewhere once, for the baseline.
#if defined(__x86_64__) && (defined(__GNUC__) || defined(__clang__))
#define SAFECELL_ROW_KERNEL [[gnu::target_clones("avx2", "default")]]
#else
#define SAFECELL_ROW_KERNEL
#endif

namespace safecell::row_kernels {

SAFECELL_ROW_KERNEL void copy_cut(const std::uint8_t* __restrict from, std::uint8_t* __restrict to,
                                  std::uint8_t mask, int count) {
  const int whole_blocks = count / kBlock * kBlock;
  for (int block = 0; block < whole_blocks; block += kBlock) {
    for (int x = block; x < block + kBlock; ++x) to[x] = from[x] & mask;
  }
  for (int x = whole_blocks; x < count; ++x) to[x] = from[x] & mask;
}

SAFECELL_ROW_KERNEL void smooth_new_row(const std::uint8_t* __restrict padded,
                                        const std::int16_t* __restrict h_two_above,
                                        const std::int16_t* __restrict h_above,
                                        std::int16_t* __restrict h_new,
                                        std::int16_t* __restrict s_new, int count) {
  for (int block = 0; block < count; block += kBlock) {
    for (int i = block; i < block + kBlock; ++i) {
      const auto h = static_cast<std::int16_t>(padded[i] + 2 * padded[i + 1] + padded[i + 2]);
      h_new[i] = h;
      s_new[i] = static_cast<std::int16_t>(h_two_above[i] + 2 * h_above[i] + h);
    }
  }
}

SAFECELL_ROW_KERNEL void add_row_to_columns(
    const std::uint8_t* __restrict pixels, const std::int16_t* __restrict s_above,
    const std::int16_t* __restrict s, const std::int16_t* __restrict s_below,
    std::uint16_t* __restrict sum, std::uint32_t* __restrict square_sum,
    std::uint8_t* __restrict minimum, std::uint8_t* __restrict maximum,
    std::uint16_t* __restrict log_sum, int count) {
  for (int block = 0; block < count; block += kBlock) {
    for (int x = block; x < block + kBlock; ++x) {
      const std::uint8_t value = pixels[x];
      sum[x] = static_cast<std::uint16_t>(sum[x] + value);
      square_sum[x] += static_cast<std::uint16_t>(value * value);  // <= 65025
      minimum[x] = std::min(minimum[x], value);
      maximum[x] = std::max(maximum[x], value);
      const auto log = static_cast<std::int16_t>(4 * s[x + 1] - s[x] - s[x + 2] - s_above[x + 1] -
                                                 s_below[x + 1]);
      log_sum[x] = static_cast<std::uint16_t>(log_sum[x] + (log < 0 ? -log : log));
    }
  }
}

SAFECELL_ROW_KERNEL void fold_columns(
    const std::uint16_t* __restrict sum, const std::uint32_t* __restrict square_sum,
    const std::uint16_t* __restrict log_sum, const std::uint8_t* __restrict minimum,
    const std::uint8_t* __restrict maximum, int cell_width, int cell_count,
    std::int64_t* __restrict cell_sum, std::int64_t* __restrict cell_square_sum,
    std::int64_t* __restrict cell_log_sum, std::uint8_t* __restrict cell_minimum,
    std::uint8_t* __restrict cell_maximum) {
  // A cell's columns in chunks of kFoldChunk, read whole and masked past the cell's last column,
  // so that each chunk is a fixed-length loop the vectoriser turns into a few reductions.
  for (int cell = 0; cell < cell_count; ++cell) {
    for (int start = 0; start < cell_width; start += kFoldChunk) {
      const int count = std::min(kFoldChunk, cell_width - start);
      const int base = cell * cell_width + start;
      std::uint32_t chunk_sum = 0;
      std::uint32_t chunk_square_sum = 0;
      std::uint32_t chunk_log_sum = 0;
      std::uint8_t chunk_minimum = 255;
      std::uint8_t chunk_maximum = 0;
      // Lanes past the cell's last column: all ones in `outside` (kept out of sums and maxima,
      // and they raise a minimum to 255, which changes nothing).
      std::uint32_t outside[kFoldChunk];
      for (int k = 0; k < kFoldChunk; ++k) outside[k] = 0U - static_cast<std::uint32_t>(k >= count);
      for (int k = 0; k < kFoldChunk; ++k) {
        chunk_sum += sum[base + k] & ~outside[k];
        chunk_square_sum += square_sum[base + k] & ~outside[k];
        chunk_log_sum += log_sum[base + k] & ~outside[k];
        const auto low_byte = static_cast<std::uint8_t>(outside[k]);
        chunk_minimum =
            std::min(chunk_minimum, static_cast<std::uint8_t>(minimum[base + k] | low_byte));
        chunk_maximum =
            std::max(chunk_maximum, static_cast<std::uint8_t>(maximum[base + k] & ~low_byte));
      }
      cell_sum[cell] += chunk_sum;
      cell_square_sum[cell] += chunk_square_sum;
      cell_log_sum[cell] += chunk_log_sum;
      cell_minimum[cell] = std::min(cell_minimum[cell], chunk_minimum);
      cell_maximum[cell] = std::max(cell_maximum[cell], chunk_maximum);
    }
  }
}

}  // namespace safecell::row_kernels
