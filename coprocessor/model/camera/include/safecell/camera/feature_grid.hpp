#pragma once
// The grid of feature cells over a camera image: the paper's 704 x 576 px frames are cut into
// 64 x 64 cells of 11 x 9 px, and each cell becomes one pixel of the feature image. Pixel
// coordinates follow OpenCV (see camera_intrinsics.hpp): a point belongs to the pixel whose
// centre is nearest, so column = floor((u + 0.5) / cell_width_px).

#include <Eigen/Core>
#include <cstddef>
#include <opencv2/core/types.hpp>
#include <optional>

namespace safecell {

struct FeatureCell {
  int column = 0;
  int row = 0;

  friend bool operator==(const FeatureCell&, const FeatureCell&) = default;
};

class FeatureGrid {
 public:
  // The paper's grid: 64 x 64 cells of 11 x 9 px over a 704 x 576 px image.
  FeatureGrid() = default;

  // `columns` x `rows` cells that tile an image of the given size exactly; throws CameraError
  // (source "feature grid") naming the size that does not divide.
  static FeatureGrid tiling(int image_width_px, int image_height_px, int columns = 64,
                            int rows = 64);

  [[nodiscard]] int columns() const { return columns_; }
  [[nodiscard]] int rows() const { return rows_; }
  [[nodiscard]] int cell_width_px() const { return cell_width_px_; }
  [[nodiscard]] int cell_height_px() const { return cell_height_px_; }
  [[nodiscard]] int image_width_px() const { return columns_ * cell_width_px_; }
  [[nodiscard]] int image_height_px() const { return rows_ * cell_height_px_; }
  [[nodiscard]] std::size_t cell_count() const;

  // The cell under a pixel position; nullopt outside the image (or not finite).
  [[nodiscard]] std::optional<FeatureCell> cell_of(const Eigen::Vector2d& pixel) const;

  // Row-major index, row * columns + column; throws CameraError for a cell outside the grid.
  [[nodiscard]] std::size_t index_of(FeatureCell cell) const;

  // The image pixels a cell covers (integer pixel indices, x = column, y = row); throws
  // CameraError for a cell outside the grid.
  [[nodiscard]] cv::Rect cell_rect_px(FeatureCell cell) const;

  friend bool operator==(const FeatureGrid&, const FeatureGrid&) = default;

 private:
  FeatureGrid(int columns, int rows, int cell_width_px, int cell_height_px);
  void check_inside(FeatureCell cell) const;

  int columns_ = 64;
  int rows_ = 64;
  int cell_width_px_ = 11;
  int cell_height_px_ = 9;
};

}  // namespace safecell
