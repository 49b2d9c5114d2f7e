#include "safecell/features/noise_cut.hpp"

#include <opencv2/core.hpp>
#include <string>

#include "image_checks.hpp"

namespace safecell {

std::uint8_t noise_cut_mask(int noise_bits) {
  if (noise_bits < 0 || noise_bits > kMaxNoiseBits) {
    throw_invalid_argument("noise_bits", std::to_string(noise_bits) + ", expected 0.." +
                                             std::to_string(kMaxNoiseBits));
  }
  return static_cast<std::uint8_t>(0xff & ~((1 << noise_bits) - 1));
}

void cut_noise_bits(const cv::Mat& frame, int noise_bits, cv::Mat& cut) {
  check_gray_image(frame, "frame");
  const std::uint8_t mask = noise_cut_mask(noise_bits);
  // OpenCV's vectorised AND; it writes in place when `cut` is `frame`.
  cv::bitwise_and(frame, cv::Scalar::all(mask), cut);
}

}  // namespace safecell
