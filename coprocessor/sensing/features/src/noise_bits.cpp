#include "safecell/features/noise_bits.hpp"

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "image_checks.hpp"
#include "safecell/features/noise_cut.hpp"

namespace safecell {
namespace {

void check_still_frames(std::span<const cv::Mat> frames) {
  if (frames.size() < 2) {
    throw_invalid_argument("still_frames", std::to_string(frames.size()) +
                                               " frames, expected at least 2 of a still scene");
  }
  check_gray_image(frames[0], "still_frames[0]");
  for (std::size_t i = 1; i < frames.size(); ++i) {
    check_gray_image_of_size(frames[i], frames[0].size(), "still_frames[" + std::to_string(i) + "]",
                             "the size of still_frames[0]");
  }
}

// Per pixel N sum(x^2) - sum(x)^2 = N (N - 1) s^2, s the sample standard deviation.
std::vector<std::uint64_t> scaled_variances(std::span<const cv::Mat> frames) {
  const int rows = frames[0].rows;
  const int columns = frames[0].cols;
  const auto pixels = static_cast<std::size_t>(rows) * static_cast<std::size_t>(columns);
  std::vector<std::uint64_t> sums(pixels, 0);
  std::vector<std::uint64_t> square_sums(pixels, 0);
  for (const cv::Mat& frame : frames) {
    for (int y = 0; y < rows; ++y) {
      const std::uint8_t* row = frame.ptr<std::uint8_t>(y);
      const std::size_t offset = static_cast<std::size_t>(y) * static_cast<std::size_t>(columns);
      for (int x = 0; x < columns; ++x) {
        const std::uint64_t value = row[x];
        sums[offset + static_cast<std::size_t>(x)] += value;
        square_sums[offset + static_cast<std::size_t>(x)] += value * value;
      }
    }
  }
  const std::uint64_t count = frames.size();
  for (std::size_t i = 0; i < pixels; ++i) {
    square_sums[i] = count * square_sums[i] - sums[i] * sums[i];
  }
  return square_sums;
}

}  // namespace

int choose_noise_bits(std::span<const cv::Mat> still_frames) {
  check_still_frames(still_frames);
  std::vector<std::uint64_t> variances = scaled_variances(still_frames);
  const auto median = variances.begin() + static_cast<std::ptrdiff_t>((variances.size() - 1) / 2);
  std::nth_element(variances.begin(), median, variances.end());
  // 2^k >= sqrt(2) sigma  <=>  4^k N (N - 1) >= 2 N (N - 1) sigma^2.
  const std::uint64_t count = still_frames.size();
  const std::uint64_t frame_pairs = count * (count - 1);
  int bits = 0;
  while (bits < kMaxNoiseBits && (std::uint64_t{1} << (2 * bits)) * frame_pairs < 2 * *median) {
    ++bits;
  }
  return bits;
}

}  // namespace safecell
