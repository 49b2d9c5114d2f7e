#include "cspace_pictures.hpp"

#include <algorithm>
#include <functional>
#include <opencv2/imgproc.hpp>

namespace safecell {
namespace {

constexpr int kMargin = 36;  // room for the title and axis names

int cell_scale(const CspaceGrid& grid, std::uint32_t axis_x, std::uint32_t axis_y) {
  const auto longest = std::max(grid.cells_along(axis_x), grid.cells_along(axis_y));
  return std::clamp(static_cast<int>(480 / std::max<std::uint32_t>(longest, 1)), 2, 24);
}

// Draws the slice through `at_cell` over two joints, one colour per cell.
cv::Mat slice(const CspaceGrid& grid, CellIndex at_cell, std::uint32_t axis_x, std::uint32_t axis_y,
              const std::string& title, const std::function<cv::Vec3b(CellIndex)>& colour) {
  const int scale = cell_scale(grid, axis_x, axis_y);
  const auto columns = static_cast<int>(grid.cells_along(axis_x));
  const auto rows = static_cast<int>(grid.cells_along(axis_y));
  cv::Mat image(rows * scale + 2 * kMargin, columns * scale + 2 * kMargin, CV_8UC3,
                cv::Scalar(255, 255, 255));
  GridCoords coords = grid.coords_of(at_cell).value();
  for (int y = 0; y < rows; ++y) {
    for (int x = 0; x < columns; ++x) {
      coords.along[axis_x] = static_cast<std::uint32_t>(x);
      coords.along[axis_y] = static_cast<std::uint32_t>(y);
      const CellIndex cell = grid.index_of(coords).value();
      const cv::Vec3b c = colour(cell);
      cv::rectangle(image, cv::Rect(kMargin + x * scale, kMargin + y * scale, scale, scale),
                    cv::Scalar(c[0], c[1], c[2]), cv::FILLED);
    }
  }
  cv::rectangle(image, cv::Rect(kMargin - 1, kMargin - 1, columns * scale + 2, rows * scale + 2),
                cv::Scalar(0, 0, 0), 1);
  cv::putText(image, title, {kMargin, kMargin - 12}, cv::FONT_HERSHEY_SIMPLEX, 0.5,
              cv::Scalar(0, 0, 0), 1);
  cv::putText(image, "joint " + std::to_string(axis_x + 1) + " ->",
              {kMargin, kMargin + rows * scale + 22}, cv::FONT_HERSHEY_SIMPLEX, 0.45,
              cv::Scalar(0, 0, 0), 1);
  cv::putText(image, "joint " + std::to_string(axis_y + 1), {2, kMargin + rows * scale / 2},
              cv::FONT_HERSHEY_SIMPLEX, 0.35, cv::Scalar(0, 0, 0), 1);
  return image;
}

}  // namespace

cv::Mat forbidden_slice(const CspaceGrid& grid, const CellSet& forbidden,
                        const CellSet& static_cells, CellIndex robot_cell, std::uint32_t axis_x,
                        std::uint32_t axis_y, const std::string& title,
                        const std::vector<CellIndex>& path) {
  cv::Mat image = slice(grid, robot_cell, axis_x, axis_y, title, [&](CellIndex cell) {
    if (cell == robot_cell) return cv::Vec3b(0, 200, 0);
    if (static_cells.test(cell)) return cv::Vec3b(0, 0, 110);
    if (forbidden.test(cell)) return cv::Vec3b(40, 40, 230);
    return cv::Vec3b(255, 255, 255);
  });
  const int scale = cell_scale(grid, axis_x, axis_y);
  std::vector<cv::Point> points;
  for (const CellIndex cell : path) {
    const auto coords = grid.coords_of(cell);
    if (!coords.ok()) continue;
    const cv::Point centre(
        kMargin + static_cast<int>(coords.value().along[axis_x]) * scale + scale / 2,
        kMargin + static_cast<int>(coords.value().along[axis_y]) * scale + scale / 2);
    if (points.empty() || points.back() != centre) points.push_back(centre);
  }
  if (points.size() > 1) {
    cv::polylines(image, points, false, cv::Scalar(120, 60, 0), 2, cv::LINE_AA);
  }
  return image;
}

cv::Mat camera_overlay(const cv::Mat& frame, const FeatureMask& blocked, const FeatureMask& robot,
                       const FeatureMask& obstacles, const std::string& label) {
  cv::Mat image;
  cv::cvtColor(frame, image, cv::COLOR_GRAY2BGR);
  const int width = frame.cols / blocked.columns();
  const int height = frame.rows / blocked.rows();
  for (int row = 0; row < blocked.rows(); ++row) {
    for (int column = 0; column < blocked.columns(); ++column) {
      cv::Scalar tint;
      if (obstacles.test(column, row)) {
        tint = cv::Scalar(0, 0, 255);
      } else if (blocked.test(column, row) && robot.test(column, row)) {
        tint = cv::Scalar(0, 220, 255);
      } else if (robot.test(column, row)) {
        tint = cv::Scalar(255, 120, 0);
      } else {
        continue;
      }
      cv::Mat cell = image(cv::Rect(column * width, row * height, width, height));
      cv::addWeighted(cell, 0.55, cv::Mat(cell.size(), cell.type(), tint), 0.45, 0.0, cell);
    }
  }
  cv::putText(image, label, {8, 24}, cv::FONT_HERSHEY_SIMPLEX, 0.7, cv::Scalar(255, 255, 255), 2);
  return image;
}

}  // namespace safecell
