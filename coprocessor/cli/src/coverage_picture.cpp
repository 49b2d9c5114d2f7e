#include "coverage_picture.hpp"

#include <opencv2/imgproc.hpp>
#include <string>
#include <vector>

#include "safecell/cli/text_table.hpp"

namespace safecell {
namespace {

constexpr double kPixelsPerMetre = 150.0;
constexpr int kMargin = 40;

// Floor point (cell frame, metres) to picture pixels: x to the right, y up.
cv::Point to_pixel(const Eigen::Vector2d& point, const CellModel& cell) {
  return {kMargin + static_cast<int>(
                        std::lround((point.x() + cell.config.size_m[0] / 2.0) * kPixelsPerMetre)),
          kMargin + static_cast<int>(
                        std::lround((cell.config.size_m[1] / 2.0 - point.y()) * kPixelsPerMetre))};
}

// Cameras that see a position: red when fewer than the threshold (a blind spot), shades of green
// from the threshold up; grey where nobody can stand.
cv::Scalar colour_of(int seeing, const FloorCoverage& coverage) {
  if (seeing < 0) return {128, 128, 128};
  if (seeing < coverage.camera_threshold) {
    return {0, 0, seeing == 0 ? 140.0 : 230.0};
  }
  const double above = static_cast<double>(seeing - coverage.camera_threshold + 1) /
                       static_cast<double>(coverage.camera_count - coverage.camera_threshold + 1);
  return {90.0 * (1.0 - above), 120.0 + 110.0 * above, 60.0 * (1.0 - above)};
}

}  // namespace

cv::Mat floor_plan(const CellModel& cell, const FloorCoverage& coverage) {
  const int width = 2 * kMargin + static_cast<int>(cell.config.size_m[0] * kPixelsPerMetre);
  const int height = 2 * kMargin + 60 + static_cast<int>(cell.config.size_m[1] * kPixelsPerMetre);
  cv::Mat plan(height, width, CV_8UC3, cv::Scalar(255, 255, 255));
  const int half = static_cast<int>(std::ceil(coverage.step_m * kPixelsPerMetre / 2.0));
  for (int row = 0; row < coverage.rows; ++row) {
    for (int column = 0; column < coverage.columns; ++column) {
      const cv::Point at = to_pixel(coverage.position_m(column, row), cell);
      cv::rectangle(plan, at - cv::Point(half, half), at + cv::Point(half, half),
                    colour_of(coverage.at(column, row), coverage), cv::FILLED);
    }
  }
  // Walls, static obstacles (their footprints), the robot's reach, the cameras.
  cv::rectangle(plan, to_pixel({-cell.config.size_m[0] / 2.0, cell.config.size_m[1] / 2.0}, cell),
                to_pixel({cell.config.size_m[0] / 2.0, -cell.config.size_m[1] / 2.0}, cell),
                {0, 0, 0}, 2);
  for (const auto& obstacle : cell.obstacles) {
    if (const auto* box = std::get_if<Box>(&obstacle.shape)) {
      std::vector<cv::Point> corners;
      for (const auto& [sx, sy] : {std::pair{-1, -1}, {1, -1}, {1, 1}, {-1, 1}}) {
        const Eigen::Vector3d corner =
            obstacle.pose * Eigen::Vector3d(sx * box->size_m.x() / 2, sy * box->size_m.y() / 2, 0);
        corners.push_back(to_pixel(corner.head<2>(), cell));
      }
      cv::polylines(plan, corners, true, {40, 40, 40}, 2);
    }
  }
  cv::circle(plan, to_pixel({0, 0}, cell), static_cast<int>(coverage.reach_m * kPixelsPerMetre),
             {160, 60, 0}, 2);
  cv::drawMarker(plan, to_pixel({0, 0}, cell), {160, 60, 0}, cv::MARKER_CROSS, 16, 2);
  for (const auto& camera : cell.cameras) {
    const cv::Point at = to_pixel(camera.position_m().head<2>(), cell);
    cv::circle(plan, at, 8, {200, 0, 0}, cv::FILLED);
    cv::putText(plan, camera.name(), at + cv::Point(-14, at.y < height / 2 ? 26 : -14),
                cv::FONT_HERSHEY_SIMPLEX, 0.5, {200, 0, 0}, 1);
  }
  const int text_y = height - 62;
  const std::string threshold = std::to_string(coverage.camera_threshold);
  const std::string legend[] = {"cameras seeing a person 0.4-2.0 m tall standing there",
                                "red: fewer than " + threshold + " (blind), green: " + threshold +
                                    " or more (darker: fewer), grey: no room to stand",
                                "blind share of the robot's reach (blue circle): " +
                                    fixed(100.0 * coverage.reach_blind_share(), 1) + " %"};
  for (int line = 0; line < 3; ++line) {
    cv::putText(plan, legend[line], {10, text_y + 20 * line}, cv::FONT_HERSHEY_SIMPLEX, 0.45,
                {0, 0, 0}, 1);
  }
  return plan;
}

}  // namespace safecell
