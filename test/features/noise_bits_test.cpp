#include "safecell/features/noise_bits.hpp"

#include <gtest/gtest.h>

#include <cstdint>
#include <opencv2/core.hpp>
#include <vector>

#include "safecell/test/property.hpp"
#include "test_frames.hpp"

namespace safecell {
namespace {

// `count` frames of one still scene (values 60..190, so noise up to 3 sigma = 60 is not clipped)
// with Gaussian noise of `sigma` gray levels, rounded to integers, independent per pixel and frame.
std::vector<cv::Mat> still_frames(std::mt19937_64& rng, double sigma, int count) {
  const cv::Mat scene = test::uniform_frame(rng, cv::Size(64, 48), 60, 190);
  std::normal_distribution<double> noise(0.0, sigma);
  std::vector<cv::Mat> frames;
  for (int i = 0; i < count; ++i) {
    cv::Mat frame(scene.size(), CV_8UC1);
    for (int y = 0; y < frame.rows; ++y) {
      for (int x = 0; x < frame.cols; ++x) {
        frame.at<std::uint8_t>(y, x) =
            cv::saturate_cast<std::uint8_t>(scene.at<std::uint8_t>(y, x) + noise(rng));
      }
    }
    frames.push_back(frame);
  }
  return frames;
}

TEST(NoiseBits, FollowTheRuleOnFramesWithKnownNoise) {
  // k = smallest k with 2^k >= sqrt(2) sigma: sigma 0 -> 0; 1 -> 1 (2 >= 1.41);
  // 4 -> 3 (8 >= 5.66 > 4); 20 -> 5 (32 >= 28.3 > 16). Each sigma sits well inside its band,
  // so the measured median does not cross a boundary.
  test::PropertyRun run(5);
  for (int i = 0; i < run.iterations(); ++i) {
    EXPECT_EQ(choose_noise_bits(still_frames(run.rng(), 0.0, 8)), 0) << "iteration " << i;
    EXPECT_EQ(choose_noise_bits(still_frames(run.rng(), 1.0, 16)), 1) << "iteration " << i;
    EXPECT_EQ(choose_noise_bits(still_frames(run.rng(), 4.0, 16)), 3) << "iteration " << i;
    EXPECT_EQ(choose_noise_bits(still_frames(run.rng(), 20.0, 16)), 5) << "iteration " << i;
  }
}

TEST(NoiseBits, BoundariesInExactArithmetic) {
  // Two frames differing by d at every pixel: s^2 = d^2 / 2, so sqrt(2) s = d exactly and
  // k = ceil(log2(d)): d = 4 -> 2, d = 5 -> 3, d = 1 -> 0, d = 200 -> 7 (the cap: 2^7 = 128 < 200).
  const auto pair_differing_by = [](int d) {
    return std::vector<cv::Mat>{cv::Mat(8, 8, CV_8UC1, cv::Scalar::all(20)),
                                cv::Mat(8, 8, CV_8UC1, cv::Scalar::all(20 + d))};
  };
  EXPECT_EQ(choose_noise_bits(pair_differing_by(1)), 0);
  EXPECT_EQ(choose_noise_bits(pair_differing_by(2)), 1);
  EXPECT_EQ(choose_noise_bits(pair_differing_by(4)), 2);
  EXPECT_EQ(choose_noise_bits(pair_differing_by(5)), 3);
  EXPECT_EQ(choose_noise_bits(pair_differing_by(8)), 3);
  EXPECT_EQ(choose_noise_bits(pair_differing_by(9)), 4);
  EXPECT_EQ(choose_noise_bits(pair_differing_by(200)), 7);
}

TEST(NoiseBits, AFewBusyPixelsDoNotMoveTheMedian) {
  test::PropertyRun run(5);
  for (int i = 0; i < run.iterations(); ++i) {
    std::vector<cv::Mat> frames = still_frames(run.rng(), 1.0, 8);
    for (std::size_t f = 0; f < frames.size(); ++f) {  // a tenth of the rows flicker wildly
      frames[f].rowRange(0, 4).setTo(cv::Scalar::all(f % 2 == 0 ? 0 : 255));
    }
    EXPECT_EQ(choose_noise_bits(frames), 1) << "iteration " << i;
  }
}

TEST(NoiseBits, RefusesTooFewOrMismatchedFrames) {
  const cv::Mat frame(8, 8, CV_8UC1, cv::Scalar::all(1));
  test::expect_invalid_argument([&] { static_cast<void>(choose_noise_bits({})); },
                                {"still_frames", "0 frames", "at least 2"});
  const std::vector<cv::Mat> one{frame};
  test::expect_invalid_argument([&] { static_cast<void>(choose_noise_bits(one)); },
                                {"still_frames", "1 frames"});
  const std::vector<cv::Mat> sizes{frame, cv::Mat(8, 9, CV_8UC1)};
  test::expect_invalid_argument([&] { static_cast<void>(choose_noise_bits(sizes)); },
                                {"still_frames[1]", "expected CV_8UC1 8 x 8 px", "9 x 8 px"});
  const std::vector<cv::Mat> types{frame, cv::Mat(8, 8, CV_8UC3)};
  test::expect_invalid_argument([&] { static_cast<void>(choose_noise_bits(types)); },
                                {"still_frames[1]", "CV_8UC3"});
  const std::vector<cv::Mat> empty_first{cv::Mat(), frame};
  test::expect_invalid_argument([&] { static_cast<void>(choose_noise_bits(empty_first)); },
                                {"still_frames[0]", "an empty image"});
}

}  // namespace
}  // namespace safecell
