#pragma once
// A set of feature cells of one camera (the paper's "pixels" of the difference image), as a
// bitmap: one bit per feature cell, rows of 64-bit words. The blocked mask, a robot silhouette
// (a row of LUT-1) and the pixels of a LUT-2 query are all FeatureMasks.

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

  friend bool operator==(const FeatureMask&, const FeatureMask&) = default;

 private:
  void check_same_shape(const FeatureMask& other) const;

  int columns_ = 0;
  int rows_ = 0;
  int words_per_row_ = 0;
  std::vector<std::uint64_t> words_;
};

}  // namespace safecell
