#include "reference_features.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <vector>

namespace safecell::test {
namespace {

// The binomial [1 2 1]^T [1 2 1] convolved with the 4-neighbour Laplacian (centre +4).
constexpr std::array<std::array<int, 5>, 5> kLogKernel{{
    {0, -1, -2, -1, 0},
    {-1, 0, 2, 0, -1},
    {-2, 2, 8, 2, -2},
    {-1, 0, 2, 0, -1},
    {0, -1, -2, -1, 0},
}};

std::uint8_t clamp_255(std::int64_t value) {
  return static_cast<std::uint8_t>(std::min<std::int64_t>(value, 255));
}

// The five features of one cell, from its pixel values and their |16 LoG|.
std::array<std::uint8_t, kFeatureCount> cell_features(const std::vector<int>& pixels,
                                                      const std::vector<int>& log16_magnitudes) {
  const auto n = static_cast<std::int64_t>(pixels.size());
  std::int64_t sum = 0;
  for (const int p : pixels) sum += p;
  // n^2 var = 1/2 sum_i sum_j (p_i - p_j)^2.
  std::int64_t pair_squares = 0;
  for (const int a : pixels) {
    for (const int b : pixels) pair_squares += std::int64_t{a - b} * (a - b);
  }
  const int low = *std::min_element(pixels.begin(), pixels.end());
  const int high = *std::max_element(pixels.begin(), pixels.end());
  std::int64_t log_sum = 0;
  for (const int l : log16_magnitudes) log_sum += l;

  std::array<std::uint8_t, kFeatureCount> features{};
  const double mean = static_cast<double>(sum) / static_cast<double>(n);
  features[static_cast<std::size_t>(Feature::kAverage)] =
      static_cast<std::uint8_t>(std::floor(mean + 0.5));
  features[static_cast<std::size_t>(Feature::kVariance)] =
      clamp_255(pair_squares / 2 / (n * n * kVarianceDivisor));
  features[static_cast<std::size_t>(Feature::kSpan)] = static_cast<std::uint8_t>(high - low);
  features[static_cast<std::size_t>(Feature::kContrast)] =
      high + low == 0 ? 0
                      : static_cast<std::uint8_t>(std::floor(
                            255.0 * (high - low) / static_cast<double>(high + low) + 0.5));
  features[static_cast<std::size_t>(Feature::kEdgeCount)] =
      clamp_255(log_sum / (n * kEdgeCountDivisor));
  return features;
}

}  // namespace

int reference_log16(const cv::Mat& frame, int x, int y) {
  int total = 0;
  for (std::size_t row = 0; row < 5; ++row) {
    for (std::size_t column = 0; column < 5; ++column) {
      const int u = std::clamp(x + static_cast<int>(column) - 2, 0, frame.cols - 1);
      const int v = std::clamp(y + static_cast<int>(row) - 2, 0, frame.rows - 1);
      total += kLogKernel[row][column] * frame.at<std::uint8_t>(v, u);
    }
  }
  return total;
}

FeatureImages reference_features(const cv::Mat& frame, const FeatureGrid& grid) {
  FeatureImages images(grid);
  for (int row = 0; row < grid.rows(); ++row) {
    for (int column = 0; column < grid.columns(); ++column) {
      const cv::Rect cell = grid.cell_rect_px(FeatureCell{column, row});
      std::vector<int> pixels;
      std::vector<int> log16_magnitudes;
      for (int y = cell.y; y < cell.y + cell.height; ++y) {
        for (int x = cell.x; x < cell.x + cell.width; ++x) {
          pixels.push_back(frame.at<std::uint8_t>(y, x));
          log16_magnitudes.push_back(std::abs(reference_log16(frame, x, y)));
        }
      }
      const auto features = cell_features(pixels, log16_magnitudes);
      for (const Feature feature : kAllFeatures) {
        images[feature].at<std::uint8_t>(row, column) = features[static_cast<std::size_t>(feature)];
      }
    }
  }
  return images;
}

}  // namespace safecell::test
