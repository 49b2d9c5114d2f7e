#include "safecell/validation/body_visibility.hpp"

#include <opencv2/core.hpp>
#include <stdexcept>
#include <vector>

namespace safecell {
namespace {

void check_size(const cv::Mat& image, int type, const FeatureGrid& grid, const char* what) {
  if (image.type() != type || image.cols != grid.columns() * grid.cell_width_px() ||
      image.rows != grid.rows() * grid.cell_height_px()) {
    throw std::invalid_argument(std::string(what) + ": an image of " + std::to_string(image.cols) +
                                " x " + std::to_string(image.rows) +
                                " pixels or of another type than the feature grid expects");
  }
}

// The feature cells in which at least half of the pixels satisfy `counts(x, y)`.
template <typename Counts>
FeatureMask half_filled_cells(const FeatureGrid& grid, Counts counts) {
  const int width = grid.cell_width_px();
  const int height = grid.cell_height_px();
  FeatureMask cells(grid);
  std::vector<int> per_column(static_cast<std::size_t>(grid.columns()));
  for (int row = 0; row < grid.rows(); ++row) {
    std::fill(per_column.begin(), per_column.end(), 0);
    for (int y = row * height; y < (row + 1) * height; ++y) {
      for (int x = 0; x < grid.columns() * width; ++x) {
        if (counts(x, y)) ++per_column[static_cast<std::size_t>(x / width)];
      }
    }
    for (int column = 0; column < grid.columns(); ++column) {
      if (2 * per_column[static_cast<std::size_t>(column)] >= width * height) {
        cells.set(column, row);
      }
    }
  }
  return cells;
}

}  // namespace

const char* to_string(UnseenReason reason) {
  switch (reason) {
    case UnseenReason::kHiddenByRobot:
      return "hidden_by_robot";
    case UnseenReason::kHiddenByStaticObstacle:
      return "hidden_by_static_obstacle";
    case UnseenReason::kHiddenByOtherBody:
      return "hidden_by_other_body";
    case UnseenReason::kOutsideViews:
      return "outside_views";
    case UnseenReason::kTooSmall:
      return "too_small";
  }
  return "unknown";
}

FeatureMask front_most_cells(const cv::Mat& object_ids, BodyCode body, const FeatureGrid& grid) {
  check_size(object_ids, CV_16UC1, grid, "object-id image");
  return half_filled_cells(grid,
                           [&](int x, int y) { return object_ids.at<BodyCode>(y, x) == body; });
}

std::vector<bool> visible_per_camera(const std::vector<cv::Mat>& object_ids, BodyCode body,
                                     const FeatureGrid& grid) {
  std::vector<bool> visible(object_ids.size());
  for (std::size_t c = 0; c < object_ids.size(); ++c) {
    visible[c] = front_most_cells(object_ids[c], body, grid).any();
  }
  return visible;
}

BodyCode scene_body_code(std::size_t humans, std::size_t b) {
  return b < humans ? body_code(BodyKind::kHuman, b) : body_code(BodyKind::kObject, b - humans);
}

FeatureMask covered_cells(const cv::Mat& coverage, const FeatureGrid& grid) {
  check_size(coverage, CV_8UC1, grid, "coverage image");
  return half_filled_cells(grid,
                           [&](int x, int y) { return coverage.at<std::uint8_t>(y, x) != 0; });
}

UnseenReason why_not_visible(const cv::Mat& object_ids, const cv::Mat& alone, BodyCode body,
                             const FeatureGrid& grid) {
  check_size(object_ids, CV_16UC1, grid, "object-id image");
  check_size(alone, CV_8UC1, grid, "coverage image");
  if (cv::countNonZero(alone) == 0) return UnseenReason::kOutsideViews;
  if (!covered_cells(alone, grid).any()) return UnseenReason::kTooSmall;
  std::size_t by_robot = 0, by_static = 0, by_other = 0;
  for (int y = 0; y < alone.rows; ++y) {
    const auto* covered = alone.ptr<std::uint8_t>(y);
    const auto* shown = object_ids.ptr<BodyCode>(y);
    for (int x = 0; x < alone.cols; ++x) {
      if (covered[x] == 0 || shown[x] == body) continue;
      switch (body_kind(shown[x])) {
        case BodyKind::kRobot:
          ++by_robot;
          break;
        case BodyKind::kStaticObstacle:
          ++by_static;
          break;
        default:
          ++by_other;
          break;
      }
    }
  }
  if (by_robot >= by_static && by_robot >= by_other) return UnseenReason::kHiddenByRobot;
  return by_static >= by_other ? UnseenReason::kHiddenByStaticObstacle
                               : UnseenReason::kHiddenByOtherBody;
}

}  // namespace safecell
