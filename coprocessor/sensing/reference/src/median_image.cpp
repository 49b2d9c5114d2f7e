#include "safecell/reference/median_image.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>
#include <vector>

namespace safecell {

cv::Mat median_image(std::span<const cv::Mat> frames) {
  if (frames.empty()) throw std::invalid_argument("median_image: no frames");
  const cv::Mat& first = frames.front();
  for (std::size_t i = 0; i < frames.size(); ++i) {
    const cv::Mat& frame = frames[i];
    if (frame.type() != CV_8UC1 || frame.size() != first.size() || frame.empty()) {
      throw std::invalid_argument("median_image: frame " + std::to_string(i) + " is " +
                                  std::to_string(frame.cols) + " x " + std::to_string(frame.rows) +
                                  " of type " + std::to_string(frame.type()) +
                                  ", expected a non-empty CV_8UC1 image of " +
                                  std::to_string(first.cols) + " x " + std::to_string(first.rows));
    }
  }
  const std::size_t count = frames.size();
  const auto middle = static_cast<std::ptrdiff_t>((count - 1) / 2);
  cv::Mat median(first.size(), CV_8UC1);
  std::vector<const std::uint8_t*> rows(count);
  std::vector<std::uint8_t> values(count);
  for (int y = 0; y < first.rows; ++y) {
    for (std::size_t i = 0; i < count; ++i) rows[i] = frames[i].ptr<std::uint8_t>(y);
    auto* out = median.ptr<std::uint8_t>(y);
    for (int x = 0; x < first.cols; ++x) {
      for (std::size_t i = 0; i < count; ++i) values[i] = rows[i][x];
      std::nth_element(values.begin(), values.begin() + middle, values.end());
      out[x] = values[static_cast<std::size_t>(middle)];
    }
  }
  return median;
}

}  // namespace safecell
