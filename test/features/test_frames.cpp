#include "test_frames.hpp"

#include <algorithm>
#include <cstdint>
#include <opencv2/core.hpp>

namespace safecell::test {
namespace {

int uniform_int(std::mt19937_64& rng, int low, int high) {
  return std::uniform_int_distribution<int>(low, high)(rng);
}

cv::Mat two_level_frame(std::mt19937_64& rng, cv::Size size) {
  const int dark = uniform_int(rng, 0, 255);
  const int bright = uniform_int(rng, 0, 255);
  cv::Mat frame(size, CV_8UC1);
  for (int y = 0; y < size.height; ++y) {
    for (int x = 0; x < size.width; ++x) {
      frame.at<std::uint8_t>(y, x) = static_cast<std::uint8_t>(rng() % 2 == 0 ? dark : bright);
    }
  }
  return frame;
}

cv::Mat constant_frame(std::mt19937_64& rng, cv::Size size) {
  const int pick = uniform_int(rng, 0, 2);
  const int value = pick == 0 ? 0 : pick == 1 ? 255 : uniform_int(rng, 0, 255);
  return cv::Mat(size, CV_8UC1, cv::Scalar::all(value));
}

cv::Mat gradient_frame(std::mt19937_64& rng, cv::Size size) {
  std::normal_distribution<double> noise(0.0, 3.0);
  const double slope_x = std::uniform_real_distribution<double>(-4.0, 4.0)(rng);
  const double slope_y = std::uniform_real_distribution<double>(-4.0, 4.0)(rng);
  cv::Mat frame(size, CV_8UC1);
  for (int y = 0; y < size.height; ++y) {
    for (int x = 0; x < size.width; ++x) {
      const double value = 128.0 + slope_x * x + slope_y * y + noise(rng);
      frame.at<std::uint8_t>(y, x) = cv::saturate_cast<std::uint8_t>(value);
    }
  }
  return frame;
}

cv::Mat rectangles_frame(std::mt19937_64& rng, cv::Size size) {
  cv::Mat frame(size, CV_8UC1, cv::Scalar::all(uniform_int(rng, 0, 255)));
  for (int i = 0; i < 6; ++i) {
    const int x = uniform_int(rng, 0, size.width - 1);
    const int y = uniform_int(rng, 0, size.height - 1);
    const cv::Rect box(x, y, uniform_int(rng, 1, size.width - x),
                       uniform_int(rng, 1, size.height - y));
    frame(box).setTo(cv::Scalar::all(uniform_int(rng, 0, 255)));
  }
  return frame;
}

}  // namespace

cv::Mat uniform_frame(std::mt19937_64& rng, cv::Size size, int low, int high) {
  cv::Mat frame(size, CV_8UC1);
  for (int y = 0; y < size.height; ++y) {
    for (int x = 0; x < size.width; ++x) {
      frame.at<std::uint8_t>(y, x) = static_cast<std::uint8_t>(uniform_int(rng, low, high));
    }
  }
  return frame;
}

cv::Mat random_frame(std::mt19937_64& rng, cv::Size size) {
  cv::Mat frame;
  switch (uniform_int(rng, 0, 5)) {
    case 0:
      frame = uniform_frame(rng, size, 0, 255);
      break;
    case 1: {
      const int centre = uniform_int(rng, 0, 255);
      frame = uniform_frame(rng, size, std::max(0, centre - 6), std::min(255, centre + 6));
      break;
    }
    case 2:
      frame = two_level_frame(rng, size);
      break;
    case 3:
      frame = constant_frame(rng, size);
      break;
    case 4:
      frame = gradient_frame(rng, size);
      break;
    default:
      frame = rectangles_frame(rng, size);
      break;
  }
  if (rng() % 3 == 0) {  // noise-cut frames: every value a multiple of 2^k
    const int keep = 0xff & ~((1 << uniform_int(rng, 1, 7)) - 1);
    cv::bitwise_and(frame, cv::Scalar::all(keep), frame);
  }
  return frame;
}

}  // namespace safecell::test
