#include "safecell/features/noise_cut.hpp"

#include <gtest/gtest.h>

#include <cstdint>
#include <opencv2/core.hpp>

#include "safecell/test/property.hpp"
#include "test_frames.hpp"

namespace safecell {
namespace {

int cut_value(int value, int noise_bits) {
  const cv::Mat frame(1, 1, CV_8UC1, cv::Scalar::all(value));
  cv::Mat cut;
  cut_noise_bits(frame, noise_bits, cut);
  return cut.at<std::uint8_t>(0, 0);
}

TEST(NoiseCut, DropsTheLowBitsOfKnownValues) {
  EXPECT_EQ(cut_value(0b1011'0111, 0), 0b1011'0111);  // 183: nothing cut
  EXPECT_EQ(cut_value(0b1011'0111, 1), 0b1011'0110);  // 182
  EXPECT_EQ(cut_value(0b1011'0111, 3), 0b1011'0000);  // 176
  EXPECT_EQ(cut_value(0b1011'0111, 7), 0b1000'0000);  // 128
  EXPECT_EQ(cut_value(127, 7), 0);
  EXPECT_EQ(cut_value(255, 2), 252);
  EXPECT_EQ(cut_value(3, 2), 0);
  EXPECT_EQ(cut_value(4, 2), 4);
}

TEST(NoiseCut, EveryPixelOfRandomFramesInPlaceOrNot) {
  test::PropertyRun run(50);
  for (int i = 0; i < run.iterations(); ++i) {
    const cv::Mat frame = test::uniform_frame(run.rng(), cv::Size(37, 23), 0, 255);
    const int bits = static_cast<int>(run.rng()() % 8);
    cv::Mat cut;
    cut_noise_bits(frame, bits, cut);
    cv::Mat in_place = frame.clone();
    cut_noise_bits(in_place, bits, in_place);
    ASSERT_EQ(cut.size(), frame.size());
    ASSERT_EQ(cut.type(), CV_8UC1);
    for (int y = 0; y < frame.rows; ++y) {
      for (int x = 0; x < frame.cols; ++x) {
        const int value = frame.at<std::uint8_t>(y, x);
        const int expected = value / (1 << bits) * (1 << bits);
        ASSERT_EQ(cut.at<std::uint8_t>(y, x), expected) << "iteration " << i << " bits " << bits;
        ASSERT_EQ(in_place.at<std::uint8_t>(y, x), expected) << "iteration " << i;
      }
    }
  }
}

TEST(NoiseCut, RefusesBadBitCountsAndFrames) {
  const cv::Mat frame(4, 4, CV_8UC1, cv::Scalar::all(9));
  cv::Mat cut;
  test::expect_invalid_argument([&] { cut_noise_bits(frame, 8, cut); },
                                {"noise_bits", "8", "expected 0..7"});
  test::expect_invalid_argument([&] { cut_noise_bits(frame, -1, cut); },
                                {"noise_bits", "-1", "expected 0..7"});
  test::expect_invalid_argument([&] { cut_noise_bits(cv::Mat(), 2, cut); },
                                {"frame", "an empty image"});
  test::expect_invalid_argument(
      [&] { cut_noise_bits(cv::Mat(4, 4, CV_8UC3), 2, cut); },
      {"frame", "expected a non-empty CV_8UC1 image", "CV_8UC3 4 x 4 px"});
}

}  // namespace
}  // namespace safecell
