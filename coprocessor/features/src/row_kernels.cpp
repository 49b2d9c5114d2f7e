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

}  // namespace safecell::row_kernels
