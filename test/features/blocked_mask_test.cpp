#include "safecell/features/blocked_mask.hpp"

#include <gtest/gtest.h>

#include <cstdint>
#include <cstdlib>
#include <opencv2/core.hpp>
#include <set>
#include <utility>

#include "safecell/features/feature_extractor.hpp"
#include "safecell/features/noise_cut.hpp"
#include "safecell/test/property.hpp"
#include "test_frames.hpp"

namespace safecell {
namespace {

// Feature images of a 2 x 1 grid with the given values in cell (0, 0); cell (1, 0) all 0.
FeatureImages two_cells(int average, int variance, int span, int contrast, int edge_count) {
  FeatureImages images(FeatureGrid::tiling(2, 1, 2, 1));
  images[Feature::kAverage].at<std::uint8_t>(0, 0) = static_cast<std::uint8_t>(average);
  images[Feature::kVariance].at<std::uint8_t>(0, 0) = static_cast<std::uint8_t>(variance);
  images[Feature::kSpan].at<std::uint8_t>(0, 0) = static_cast<std::uint8_t>(span);
  images[Feature::kContrast].at<std::uint8_t>(0, 0) = static_cast<std::uint8_t>(contrast);
  images[Feature::kEdgeCount].at<std::uint8_t>(0, 0) = static_cast<std::uint8_t>(edge_count);
  return images;
}

TEST(BlockedMask, DistanceByHand) {
  const FeatureImages current = two_cells(100, 10, 50, 30, 5);
  const FeatureImages reference = two_cells(90, 12, 50, 40, 9);
  const FeatureWeights weights{.average = 1, .variance = 2, .span = 7, .contrast = 1};
  // 1 * |100 - 90| + 2 * |10 - 12| + 7 * |50 - 50| + 1 * |30 - 40| + 0 * |5 - 9| = 24.
  const cv::Mat distance = feature_distance(current, reference, weights);
  ASSERT_EQ(distance.type(), CV_32SC1);
  ASSERT_EQ(distance.size(), cv::Size(2, 1));
  EXPECT_EQ(distance.at<std::int32_t>(0, 0), 24);
  EXPECT_EQ(distance.at<std::int32_t>(0, 1), 0);
  // Blocked only where the distance exceeds the threshold.
  const cv::Mat at_24 = blocked_mask(current, reference, weights, 24);
  ASSERT_EQ(at_24.type(), CV_8UC1);
  EXPECT_EQ(at_24.at<std::uint8_t>(0, 0), 0);
  EXPECT_EQ(blocked_mask(current, reference, weights, 23).at<std::uint8_t>(0, 0), 255);
  EXPECT_EQ(blocked_mask(current, reference, weights, 0).at<std::uint8_t>(0, 1), 0);
  // The largest distance there is: every feature from 0 to 255 at the largest weight.
  const FeatureWeights all_max{255, 255, 255, 255, 255};
  EXPECT_EQ(feature_distance(two_cells(255, 255, 255, 255, 255), two_cells(0, 0, 0, 0, 0), all_max)
                .at<std::int32_t>(0, 0),
            5 * 255 * 255);
}

FeatureImages random_feature_images(std::mt19937_64& rng, const FeatureGrid& grid) {
  FeatureImages images(grid);
  for (const Feature feature : kAllFeatures) {
    images[feature] = test::uniform_frame(rng, images[feature].size(), 0, 255);
  }
  return images;
}

TEST(BlockedMask, MatchesADirectSumOnRandomImages) {
  test::PropertyRun run(100);
  const FeatureGrid grid = FeatureGrid::tiling(70, 54, 10, 6);
  std::uniform_int_distribution<int> weight(0, kMaxFeatureWeight), threshold(0, 100000);
  for (int i = 0; i < run.iterations(); ++i) {
    const FeatureImages current = random_feature_images(run.rng(), grid);
    const FeatureImages reference = random_feature_images(run.rng(), grid);
    FeatureWeights weights{weight(run.rng()), weight(run.rng()), weight(run.rng()),
                           weight(run.rng()), weight(run.rng())};
    if (run.rng()() % 2 == 0) weights.variance = 0;
    if (weights.average + weights.variance + weights.span + weights.contrast + weights.edge_count ==
        0) {
      weights.edge_count = 1;
    }
    const int limit = threshold(run.rng());
    const cv::Mat distance = feature_distance(current, reference, weights);
    const cv::Mat mask = blocked_mask(current, reference, weights, limit);
    for (int row = 0; row < grid.rows(); ++row) {
      for (int column = 0; column < grid.columns(); ++column) {
        int expected = 0;
        for (const Feature feature : kAllFeatures) {
          expected +=
              weights.of(feature) * std::abs(current[feature].at<std::uint8_t>(row, column) -
                                             reference[feature].at<std::uint8_t>(row, column));
        }
        ASSERT_EQ(distance.at<std::int32_t>(row, column), expected) << "iteration " << i;
        ASSERT_EQ(mask.at<std::uint8_t>(row, column), expected > limit ? 255 : 0)
            << "iteration " << i;
      }
    }
  }
}

// A textured frame with sensor noise (sigma 2), noise-cut by 2 bits as a camera would be.
cv::Mat noisy_cut(const cv::Mat& scene, std::mt19937_64& rng) {
  std::normal_distribution<double> noise(0.0, 2.0);
  cv::Mat frame(scene.size(), CV_8UC1);
  for (int y = 0; y < frame.rows; ++y) {
    for (int x = 0; x < frame.cols; ++x) {
      frame.at<std::uint8_t>(y, x) =
          cv::saturate_cast<std::uint8_t>(scene.at<std::uint8_t>(y, x) + noise(rng));
    }
  }
  cut_noise_bits(frame, 2, frame);
  return frame;
}

TEST(BlockedMask, ABrightSquareBlocksExactlyTheCellsItCovers) {
  test::PropertyRun run(5);
  FeatureExtractor extractor;  // 64 x 64 cells of 11 x 9 px
  // The square covers x 107..216, y 95..184: columns 107 / 11 = 9 (3 of its 11 px) to
  // 216 / 11 = 19 (8 px), rows 95 / 9 = 10 (4 of 9 px) to 184 / 9 = 20 (5 px): 11 x 11 cells.
  const cv::Rect square(107, 95, 110, 90);
  std::set<std::pair<int, int>> covered;
  for (int y = square.y; y < square.y + square.height; ++y) {
    for (int x = square.x; x < square.x + square.width; ++x) covered.emplace(x / 11, y / 9);
  }
  ASSERT_EQ(covered.size(), 121u);
  // The texture spans 40..140, so a single covered pixel (255) raises a cell's span by 100 or
  // more, while noise moves the span and the average by a few levels.
  const FeatureWeights weights{.average = 1, .span = 1};
  constexpr int kThreshold = 40;
  for (int i = 0; i < run.iterations(); ++i) {
    const cv::Mat scene = test::uniform_frame(run.rng(), cv::Size(704, 576), 40, 140);
    const FeatureImages reference = extractor.extract(noisy_cut(scene, run.rng()));
    cv::Mat with_square = scene.clone();
    with_square(square).setTo(cv::Scalar::all(255));
    const FeatureImages current = extractor.extract(noisy_cut(with_square, run.rng()));

    const cv::Mat mask = blocked_mask(current, reference, weights, kThreshold);
    ASSERT_EQ(mask.size(), cv::Size(64, 64));
    EXPECT_EQ(cv::countNonZero(mask), 121) << "iteration " << i;
    for (int row = 0; row < 64; ++row) {
      for (int column = 0; column < 64; ++column) {
        const bool blocked = mask.at<std::uint8_t>(row, column) == 255;
        EXPECT_EQ(blocked, covered.count({column, row}) == 1)
            << "iteration " << i << " cell (column " << column << ", row " << row << ")";
      }
    }
    // The same frames, no square: nothing blocked.
    const FeatureImages again = extractor.extract(noisy_cut(scene, run.rng()));
    EXPECT_EQ(cv::countNonZero(blocked_mask(again, reference, weights, kThreshold)), 0);
  }
}

TEST(BlockedMask, RefusesBadParameters) {
  const FeatureImages images(FeatureGrid::tiling(4, 4, 2, 2));
  const FeatureWeights weights{.average = 1};
  test::expect_invalid_argument(
      [&] { static_cast<void>(blocked_mask(images, images, weights, -1)); },
      {"threshold", "-1", "expected >= 0"});
  test::expect_invalid_argument(
      [&] { static_cast<void>(blocked_mask(images, images, FeatureWeights{}, 10)); },
      {"weights", "all 0"});
  test::expect_invalid_argument(
      [&] { static_cast<void>(blocked_mask(images, images, FeatureWeights{.span = -2}, 10)); },
      {"weights.span", "-2", "expected 0..255"});
  test::expect_invalid_argument(
      [&] {
        static_cast<void>(blocked_mask(images, images, FeatureWeights{.edge_count = 256}, 10));
      },
      {"weights.edge_count", "256"});

  const FeatureImages other_grid(FeatureGrid::tiling(8, 4, 2, 2));
  test::expect_invalid_argument(
      [&] { static_cast<void>(blocked_mask(images, other_grid, weights, 10)); },
      {"reference", "feature grid 2 x 2 cells of 4 x 2 px",
       "expected the grid of current, 2 x 2 cells of 2 x 2 px"});

  FeatureImages broken = images.clone();
  broken[Feature::kContrast] = cv::Mat(3, 2, CV_8UC1);
  test::expect_invalid_argument(
      [&] { static_cast<void>(feature_distance(broken, images, weights)); },
      {"current.contrast", "expected CV_8UC1 2 x 2 px", "got CV_8UC1 2 x 3 px"});
  broken[Feature::kContrast] = cv::Mat(2, 2, CV_32SC1);
  test::expect_invalid_argument(
      [&] { static_cast<void>(feature_distance(images, broken, weights)); },
      {"reference.contrast", "got CV_32SC1 2 x 2 px"});
}

}  // namespace
}  // namespace safecell
