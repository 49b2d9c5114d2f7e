#include "safecell/camera/feature_grid.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "safecell/camera/camera_error.hpp"

namespace safecell {
namespace {

constexpr const char* kSource = "feature grid";

// The cell size along one axis that `count` cells tiling `image_px` pixels have.
int tile(const char* field, int image_px, int count, const char* cells) {
  if (count <= 0) {
    throw_camera_error(kSource, std::string(cells),
                       std::to_string(count) + ", expected a number of cells > 0");
  }
  if (image_px <= 0 || image_px % count != 0) {
    throw_camera_error(kSource, field,
                       std::to_string(image_px) + " px, expected a positive multiple of the " +
                           std::to_string(count) + " " + cells + " so that they tile it exactly");
  }
  return image_px / count;
}

// The pixel index under a position along one axis, or -1 outside [-0.5, size_px - 0.5).
int pixel_index(double position_px, int size_px) {
  if (!(position_px >= -0.5 && position_px < size_px - 0.5)) return -1;
  // Rounding may carry a position just below the far edge onto it.
  return std::min(static_cast<int>(std::floor(position_px + 0.5)), size_px - 1);
}

}  // namespace

FeatureGrid::FeatureGrid(int columns, int rows, int cell_width_px, int cell_height_px)
    : columns_(columns),
      rows_(rows),
      cell_width_px_(cell_width_px),
      cell_height_px_(cell_height_px) {}

FeatureGrid FeatureGrid::tiling(int image_width_px, int image_height_px, int columns, int rows) {
  const int cell_width_px = tile("image_width_px", image_width_px, columns, "columns");
  const int cell_height_px = tile("image_height_px", image_height_px, rows, "rows");
  return FeatureGrid(columns, rows, cell_width_px, cell_height_px);
}

std::size_t FeatureGrid::cell_count() const {
  return static_cast<std::size_t>(columns_) * static_cast<std::size_t>(rows_);
}

std::optional<FeatureCell> FeatureGrid::cell_of(const Eigen::Vector2d& pixel) const {
  const int u = pixel_index(pixel.x(), image_width_px());
  const int v = pixel_index(pixel.y(), image_height_px());
  if (u < 0 || v < 0) return std::nullopt;
  return FeatureCell{u / cell_width_px_, v / cell_height_px_};
}

std::size_t FeatureGrid::index_of(FeatureCell cell) const {
  check_inside(cell);
  return static_cast<std::size_t>(cell.row) * static_cast<std::size_t>(columns_) +
         static_cast<std::size_t>(cell.column);
}

cv::Rect FeatureGrid::cell_rect_px(FeatureCell cell) const {
  check_inside(cell);
  return {cell.column * cell_width_px_, cell.row * cell_height_px_, cell_width_px_,
          cell_height_px_};
}

void FeatureGrid::check_inside(FeatureCell cell) const {
  if (cell.column < 0 || cell.column >= columns_ || cell.row < 0 || cell.row >= rows_) {
    throw_camera_error(
        kSource, "cell",
        "(column " + std::to_string(cell.column) + ", row " + std::to_string(cell.row) +
            ") is outside the grid, expected columns 0.." + std::to_string(columns_ - 1) +
            " and rows 0.." + std::to_string(rows_ - 1));
  }
}

}  // namespace safecell
