#pragma once
// A set of feature cells of one camera (the paper's "pixels" of the difference image), as a
// bitmap: one bit per feature cell, rows of 64-bit words. The blocked mask, a robot silhouette
// (a row of LUT-1) and the pixels of a LUT-2 query are all FeatureMasks.

#include <algorithm>
#include <bit>
#include <cstdint>
#include <opencv2/core/mat.hpp>
#include <vector>

#include "safecell/camera/feature_grid.hpp"

namespace safecell {

// Feature cells col0..col1 x row0..row1, both ends included.
struct FeatureRect {
  std::uint16_t col0 = 0;
  std::uint16_t row0 = 0;
  std::uint16_t col1 = 0;
  std::uint16_t row1 = 0;

  friend bool operator==(const FeatureRect&, const FeatureRect&) = default;
};

class FeatureMask {
 public:
  FeatureMask() = default;
  // All clear. Throws std::invalid_argument for a size outside 1..65535.
  FeatureMask(int columns, int rows);
  explicit FeatureMask(const FeatureGrid& grid) : FeatureMask(grid.columns(), grid.rows()) {}
  // From a CV_8UC1 image of the mask's size: non-zero = set. Throws std::invalid_argument for
  // another type or an empty image.
  static FeatureMask from_image(const cv::Mat& mask);

  [[nodiscard]] int columns() const { return columns_; }
  [[nodiscard]] int rows() const { return rows_; }
  [[nodiscard]] int words_per_row() const { return words_per_row_; }

  [[nodiscard]] bool test(int column, int row) const {
    return ((row_words(row)[column >> 6] >> (column & 63)) & 1U) != 0;
  }
  void set(int column, int row) {
    row_words(row)[column >> 6] |= std::uint64_t{1} << (column & 63);
  }
  void reset(int column, int row) {
    row_words(row)[column >> 6] &= ~(std::uint64_t{1} << (column & 63));
  }
  // Sets the rectangle clipped to the mask (precondition: col0 <= col1, row0 <= row1).
  void set_rect(const FeatureRect& rect);
  // Clears the rectangle clipped to the mask.
  void reset_rect(const FeatureRect& rect);
  // Whether every cell of the rectangle clipped to the mask is set.
  [[nodiscard]] bool all_in_rect(const FeatureRect& rect) const;
  // Whether some cell of the rectangle clipped to the mask is set.
  [[nodiscard]] bool any_in_rect(const FeatureRect& rect) const;
  // Calls visit(block column, block row) for every block of size x size cells (aligned to
  // multiples of size, clipped to the mask) whose cells are all set, row by row, until it returns
  // true; returns whether it did. `size`: a power of two, 1..64 (throws std::invalid_argument
  // otherwise). Word-parallel: a few word operations per row of blocks. `visit` may clear cells
  // of the blocks it was given.
  template <typename Visit>
  bool for_each_full_block(int size, Visit visit) const;
  // Calls visit(column, row) for every set cell, row by row (a word scan, not a test per cell).
  template <typename Visit>
  void for_each_set(Visit visit) const;
  void clear();

  [[nodiscard]] std::size_t count() const;
  [[nodiscard]] bool any() const;
  [[nodiscard]] bool intersects(const FeatureMask& other) const;

  FeatureMask& operator|=(const FeatureMask& other);
  FeatureMask& operator&=(const FeatureMask& other);
  // Removes the cells of `other`.
  FeatureMask& subtract(const FeatureMask& other);
  // Grows every set cell into the rectangle of +-columns x +-rows around it (clipped to the mask;
  // precondition: both >= 0).
  void dilate(int columns, int rows);

  [[nodiscard]] std::uint64_t* row_words(int row) {
    return words_.data() + static_cast<std::size_t>(row) * static_cast<std::size_t>(words_per_row_);
  }
  [[nodiscard]] const std::uint64_t* row_words(int row) const {
    return words_.data() + static_cast<std::size_t>(row) * static_cast<std::size_t>(words_per_row_);
  }

  // CV_8UC1, 255 where set.
  [[nodiscard]] cv::Mat to_image() const;

  // The set cells as rectangles: runs of each row, merged with the run of the same extent in the
  // row above. Exact: their union is the mask, and they do not overlap.
  [[nodiscard]] std::vector<FeatureRect> rectangles() const;
  // The same, appended to `out` (no allocation once `out` and this thread's scratch have grown).
  void append_rectangles(std::vector<FeatureRect>& out) const;

  friend bool operator==(const FeatureMask&, const FeatureMask&) = default;

 private:
  // Bits 0, size, 2 size, ... of a word; throws std::invalid_argument unless size is a power of
  // two 1..64.
  static std::uint64_t block_start_bits(int size);

  void check_same_shape(const FeatureMask& other) const;

  int columns_ = 0;
  int rows_ = 0;
  int words_per_row_ = 0;
  std::vector<std::uint64_t> words_;
};

template <typename Visit>
void FeatureMask::for_each_set(Visit visit) const {
  for (int row = 0; row < rows_; ++row) {
    const std::uint64_t* words = row_words(row);
    for (int word = 0; word < words_per_row_; ++word) {
      for (std::uint64_t bits = words[word]; bits != 0; bits &= bits - 1) {
        visit(word * 64 + std::countr_zero(bits), row);
      }
    }
  }
}

template <typename Visit>
bool FeatureMask::for_each_full_block(int size, Visit visit) const {
  const std::uint64_t block_starts = block_start_bits(size);
  const int blocks_per_word = 64 / size;
  for (int block_row = 0; block_row * size < rows_; ++block_row) {
    const int row_end = std::min(rows_, (block_row + 1) * size);
    for (int word = 0; word < words_per_row_; ++word) {
      std::uint64_t all = ~std::uint64_t{0};
      for (int row = block_row * size; row < row_end; ++row) all &= row_words(row)[word];
      std::uint64_t starts = block_starts;
      const int columns_in_word = std::min(64, columns_ - word * 64);
      if (columns_in_word < 64) {
        // Cells past the last column count as set (blocks are clipped); no block starts there.
        all |= ~std::uint64_t{0} << columns_in_word;
        starts &= (std::uint64_t{1} << columns_in_word) - 1;
      }
      // Bit k of `all` becomes the AND of bits k .. k + size - 1.
      for (int shift = 1; shift < size; shift *= 2) all &= all >> shift;
      for (std::uint64_t full = all & starts; full != 0; full &= full - 1) {
        const int block_column = word * blocks_per_word + std::countr_zero(full) / size;
        if (visit(block_column, block_row)) return true;
      }
    }
  }
  return false;
}

}  // namespace safecell
