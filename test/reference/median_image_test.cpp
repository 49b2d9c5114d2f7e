#include "safecell/reference/median_image.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <stdexcept>
#include <vector>

#include "safecell/test/property.hpp"

namespace safecell {
namespace {

cv::Mat constant(int value) { return cv::Mat(2, 3, CV_8UC1, cv::Scalar(value)); }

TEST(MedianImage, ByHand) {
  // Odd count: the middle value, (10, 200, 30) -> 30.
  const std::vector<cv::Mat> three{constant(10), constant(200), constant(30)};
  EXPECT_EQ(median_image(three).at<std::uint8_t>(1, 2), 30);
  // Even count: the lower of the two middle values, (1, 2, 3, 4) -> 2.
  const std::vector<cv::Mat> four{constant(4), constant(1), constant(3), constant(2)};
  EXPECT_EQ(median_image(four).at<std::uint8_t>(0, 0), 2);
}

TEST(MedianImage, EqualsSortingEveryPixel) {
  test::PropertyRun run(20);
  for (int i = 0; i < run.iterations(); ++i) {
    const int count = 1 + static_cast<int>(run.rng()() % 12);
    std::vector<cv::Mat> frames;
    for (int f = 0; f < count; ++f) {
      cv::Mat frame(17, 23, CV_8UC1);
      for (int p = 0; p < frame.rows * frame.cols; ++p) {
        frame.data[p] = static_cast<std::uint8_t>(run.rng()() % 256);
      }
      frames.push_back(frame);
    }
    const cv::Mat median = median_image(frames);
    for (int y = 0; y < median.rows; ++y) {
      for (int x = 0; x < median.cols; ++x) {
        std::vector<int> values;
        for (const auto& frame : frames) values.push_back(frame.at<std::uint8_t>(y, x));
        std::sort(values.begin(), values.end());
        ASSERT_EQ(median.at<std::uint8_t>(y, x), values[static_cast<std::size_t>((count - 1) / 2)])
            << "iteration " << i << " pixel " << x << "," << y;
      }
    }
  }
}

TEST(MedianImage, RefusesMismatchedFrames) {
  EXPECT_THROW(static_cast<void>(median_image(std::vector<cv::Mat>{})), std::invalid_argument);
  const std::vector<cv::Mat> sizes{constant(1), cv::Mat(3, 3, CV_8UC1, cv::Scalar(1))};
  EXPECT_THROW(static_cast<void>(median_image(sizes)), std::invalid_argument);
  const std::vector<cv::Mat> types{constant(1), cv::Mat(2, 3, CV_16UC1, cv::Scalar(1))};
  try {
    static_cast<void>(median_image(types));
    FAIL() << "no error";
  } catch (const std::invalid_argument& error) {
    EXPECT_NE(std::string(error.what()).find("frame 1"), std::string::npos) << error.what();
  }
}

}  // namespace
}  // namespace safecell
