#pragma once
// The row loops of the feature extractor, written for the vectoriser: each walks `count` entries
// (a multiple of kBlock unless said otherwise) in blocks of kBlock, and the block loop has a trip
// count known at compile time, which GCC's -O2 cost model needs to vectorise it; __restrict (a GCC
// and Clang extension) tells it the rows do not overlap. On x86-64 each is also compiled for AVX2
// and the loader picks that version on CPUs that have it (row_kernels.cpp). Real-time safe: no
// allocation, no branches on pixel values beyond min/max.

#include <cstdint>

namespace safecell::row_kernels {

// 32 pixels: one AVX2 register of bytes, two SSE2 ones.
inline constexpr int kBlock = 32;

// to[x] = from[x] & mask for x < count (any count: whole blocks, then the rest one by one), the
// noise cut applied as a frame row is read.
void copy_cut(const std::uint8_t* __restrict from, std::uint8_t* __restrict to, std::uint8_t mask,
              int count);

// The LoG's smoothing, one new frame row at a time. `padded` is the new frame row k with its
// edges replicated (entry i is column i - 2); h_new = H(k), its binomial [1 2 1] along the row;
// s_new = S(k - 1) = H(k - 2) + 2 H(k - 1) + H(k), the binomial across rows. Entry i of H and S
// is column i - 1. H <= 4 * 255 and S <= 16 * 255 fit 16 bits.
void smooth_new_row(const std::uint8_t* __restrict padded,
                    const std::int16_t* __restrict h_two_above,
                    const std::int16_t* __restrict h_above, std::int16_t* __restrict h_new,
                    std::int16_t* __restrict s_new, int count);

// Per-column partial sums cover at most kMaxPartialRows rows: 16 * 255 and 16 * 4080 fit the
// 16-bit sums, 16 * 255^2 the 32-bit one.
inline constexpr int kMaxPartialRows = 16;

// One frame row into the per-column partials: its pixels (sum, sum of squares, min, max) and its
// |LoG| = |4 S(x) - S(x - 1) - S(x + 1) - S_above(x) - S_below(x)| (the 4-neighbour Laplacian of
// the smoothed rows S, whose entry i is column i - 1; |LoG| <= 4080, see feature_images.hpp).
void add_row_to_columns(const std::uint8_t* __restrict pixels,
                        const std::int16_t* __restrict s_above, const std::int16_t* __restrict s,
                        const std::int16_t* __restrict s_below, std::uint16_t* __restrict sum,
                        std::uint32_t* __restrict square_sum, std::uint8_t* __restrict minimum,
                        std::uint8_t* __restrict maximum, std::uint16_t* __restrict log_sum,
                        int count);

// Columns a cell's fold reads at a time (fold_columns).
inline constexpr int kFoldChunk = 16;

// The per-column partials folded into the cells of a cell row: cells of `cell_width` columns side
// by side from column 0; per cell the partials of its columns are added to cell_sum,
// cell_square_sum and cell_log_sum, and cell_minimum and cell_maximum are narrowed. The column
// rows hold cell_count * cell_width entries and are read up to kFoldChunk - 1 entries past them
// (which must be readable; their values do not matter). Per chunk the sums stay within 32 bits:
// 16 columns of kMaxPartialRows rows.
void fold_columns(const std::uint16_t* __restrict sum, const std::uint32_t* __restrict square_sum,
                  const std::uint16_t* __restrict log_sum, const std::uint8_t* __restrict minimum,
                  const std::uint8_t* __restrict maximum, int cell_width, int cell_count,
                  std::int64_t* __restrict cell_sum, std::int64_t* __restrict cell_square_sum,
                  std::int64_t* __restrict cell_log_sum, std::uint8_t* __restrict cell_minimum,
                  std::uint8_t* __restrict cell_maximum);

}  // namespace safecell::row_kernels
