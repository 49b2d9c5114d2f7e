#include "safecell/features/feature_extractor.hpp"

#include <gtest/gtest.h>

#include <array>
#include <cstdint>
#include <opencv2/core.hpp>
#include <string>
#include <vector>

#include "reference_features.hpp"
#include "safecell/features/noise_cut.hpp"
#include "safecell/test/property.hpp"
#include "test_frames.hpp"

namespace safecell {
namespace {

// The first cell where the two feature images differ, or "" where they agree exactly.
std::string first_difference(const FeatureImages& actual, const FeatureImages& expected) {
  for (const Feature feature : kAllFeatures) {
    for (int row = 0; row < expected.grid.rows(); ++row) {
      for (int column = 0; column < expected.grid.columns(); ++column) {
        const int a = actual[feature].at<std::uint8_t>(row, column);
        const int e = expected[feature].at<std::uint8_t>(row, column);
        if (a != e) {
          return std::string(feature_name(feature)) + " at (column " + std::to_string(column) +
                 ", row " + std::to_string(row) + "): " + std::to_string(a) + ", expected " +
                 std::to_string(e);
        }
      }
    }
  }
  return "";
}

// The five features of cell (column, row), in Feature order.
std::array<int, kFeatureCount> features_at(const FeatureImages& images, int column, int row) {
  std::array<int, kFeatureCount> values{};
  for (const Feature feature : kAllFeatures) {
    values[static_cast<std::size_t>(feature)] = images[feature].at<std::uint8_t>(row, column);
  }
  return values;
}

using Features = std::array<int, kFeatureCount>;  // average, variance, span, contrast, edge count

cv::Mat frame_of_rows(const std::vector<std::vector<int>>& rows) {
  cv::Mat frame(static_cast<int>(rows.size()), static_cast<int>(rows[0].size()), CV_8UC1);
  for (int y = 0; y < frame.rows; ++y) {
    for (int x = 0; x < frame.cols; ++x) {
      frame.at<std::uint8_t>(y, x) =
          static_cast<std::uint8_t>(rows[static_cast<std::size_t>(y)][static_cast<std::size_t>(x)]);
    }
  }
  return frame;
}

TEST(FeatureExtractor, ConstantCellsHaveOnlyAnAverage) {
  const FeatureGrid grid = FeatureGrid::tiling(6, 4, 2, 2);  // cells of 3 x 2 px
  FeatureExtractor extractor(grid);
  cv::Mat frame(4, 6, CV_8UC1, cv::Scalar::all(100));
  const FeatureImages images = extractor.extract(frame);
  for (int row = 0; row < 2; ++row) {
    for (int column = 0; column < 2; ++column) {
      EXPECT_EQ(features_at(images, column, row), (Features{100, 0, 0, 0, 0}));
    }
  }
  // Black: max + min = 0, so the contrast is 0 by definition.
  frame.setTo(cv::Scalar::all(0));
  EXPECT_EQ(features_at(extractor.extract(frame), 1, 1), (Features{0, 0, 0, 0, 0}));
}

TEST(FeatureExtractor, TwoLevelCellsByHand) {
  // One cell of 4 x 2 px: 10 10 30 30 in both rows. n = 8, sum = 160: average 20.
  // n sum(p^2) - sum^2 = 8 * 4000 - 25600 = 6400, var = 6400 / 64 = 100, 100 / 16 = 6.25 -> 6.
  // span 20; contrast 255 * 20 / 40 = 127.5 -> 128 (ties up).
  // The rows are equal, so the 5 x 5 kernel acts as its column sums along the row,
  // [-4 0 8 0 -4]; on 10 10 | 10 10 30 30 | 30 30 (edges replicated) every pixel gives
  // |8 p(x) - 4 p(x - 2) - 4 p(x + 2)| = 80; sum 640 / (8 * 4) = 20.
  FeatureExtractor small(FeatureGrid::tiling(4, 2, 1, 1));
  const cv::Mat step = frame_of_rows({{10, 10, 30, 30}, {10, 10, 30, 30}});
  EXPECT_EQ(features_at(small.extract(step), 0, 0), (Features{20, 6, 20, 128, 20}));

  // One cell of 11 x 9 px (the paper's size): 5 columns of 40, then 6 columns of 100.
  // n = 99, sum = 9 * 800 = 7200: 72.73 -> 73. sum(p^2) = 9 * 68000 = 612000;
  // 99 * 612000 - 7200^2 = 8748000; / (99^2 * 16) = 55.8 -> 55. span 60;
  // contrast 255 * 60 / 140 = 109.3 -> 109. |16 LoG| along a row: 240 at x = 3, 4, 5, 6, else 0,
  // so 9 * 960 = 8640; / (99 * 4) = 21.8 -> 21.
  FeatureExtractor paper_cell(FeatureGrid::tiling(11, 9, 1, 1));
  cv::Mat edge(9, 11, CV_8UC1, cv::Scalar::all(100));
  edge(cv::Rect(0, 0, 5, 9)).setTo(cv::Scalar::all(40));
  EXPECT_EQ(features_at(paper_cell.extract(edge), 0, 0), (Features{73, 55, 60, 109, 21}));

  // A 2 x 2 checkerboard of 0 and 255: average 127.5 -> 128; var = 16256.25, / 16 = 1016 ->
  // clamped to 255; span 255; contrast 255; every pixel's |16 LoG| is 4 * 255 = 1020, so
  // 4080 / (4 * 4) = 255.
  FeatureExtractor tiny(FeatureGrid::tiling(2, 2, 1, 1));
  const cv::Mat checker = frame_of_rows({{0, 255}, {255, 0}});
  EXPECT_EQ(features_at(tiny.extract(checker), 0, 0), (Features{128, 255, 255, 255, 255}));
}

TEST(FeatureExtractor, MatchesTheReferenceOnRandomFramesAndGrids) {
  test::PropertyRun run(200);
  // Cells wider than 16 px too: their columns are folded in chunks of 16.
  std::uniform_int_distribution<int> cells(1, 7), cell_width_px(1, 40), cell_height_px(1, 11);
  for (int i = 0; i < run.iterations(); ++i) {
    const int columns = cells(run.rng());
    const int rows = cells(run.rng());
    const FeatureGrid grid = FeatureGrid::tiling(columns * cell_width_px(run.rng()),
                                                 rows * cell_height_px(run.rng()), columns, rows);
    const cv::Mat frame =
        test::random_frame(run.rng(), cv::Size(grid.image_width_px(), grid.image_height_px()));
    FeatureExtractor extractor(grid);
    ASSERT_EQ(first_difference(extractor.extract(frame), test::reference_features(frame, grid)), "")
        << "iteration " << i << ", grid " << columns << " x " << rows << " cells of "
        << grid.cell_width_px() << " x " << grid.cell_height_px() << " px";
  }
}

TEST(FeatureExtractor, MatchesTheReferenceOnThePaperGrid) {
  test::PropertyRun run(3);
  FeatureExtractor extractor;  // 64 x 64 cells of 11 x 9 px over 704 x 576
  FeatureImages images;
  for (int i = 0; i < run.iterations(); ++i) {
    const cv::Mat frame = test::random_frame(run.rng(), cv::Size(704, 576));
    extractor.extract(frame, images);  // the same images reused every time
    ASSERT_EQ(first_difference(images, test::reference_features(frame, extractor.grid())), "")
        << "iteration " << i;
  }
}

// Cells taller than 16 rows: the 16-bit column sums must be folded in before they overflow.
// Vertical stripes two pixels wide have |16 LoG| = 2040 inside (8 * 255), so 33 rows of them
// would overflow a 16-bit sum.
TEST(FeatureExtractor, TallCellsOfStrongEdges) {
  test::PropertyRun run(20);
  std::uniform_int_distribution<int> cell_height_px(17, 70);
  for (int i = 0; i < run.iterations(); ++i) {
    const FeatureGrid grid = FeatureGrid::tiling(24, 2 * cell_height_px(run.rng()), 3, 2);
    cv::Mat frame(grid.image_height_px(), grid.image_width_px(), CV_8UC1);
    for (int y = 0; y < frame.rows; ++y) {
      for (int x = 0; x < frame.cols; ++x) frame.at<std::uint8_t>(y, x) = x % 4 < 2 ? 255 : 0;
    }
    if (i % 2 == 1) frame = test::random_frame(run.rng(), frame.size());
    FeatureExtractor extractor(grid);
    ASSERT_EQ(first_difference(extractor.extract(frame), test::reference_features(frame, grid)), "")
        << "iteration " << i << ", cells of " << grid.cell_height_px() << " rows";
  }
}

TEST(FeatureExtractor, ItsOwnNoiseCutEqualsCuttingFirst) {
  test::PropertyRun run(100);
  std::uniform_int_distribution<int> cells(1, 5), cell_width_px(1, 12), cell_height_px(1, 10),
      bits(0, kMaxNoiseBits);
  for (int i = 0; i < run.iterations(); ++i) {
    const int columns = cells(run.rng());
    const int rows = cells(run.rng());
    const FeatureGrid grid = FeatureGrid::tiling(columns * cell_width_px(run.rng()),
                                                 rows * cell_height_px(run.rng()), columns, rows);
    const cv::Mat frame =
        test::random_frame(run.rng(), cv::Size(grid.image_width_px(), grid.image_height_px()));
    const int noise_bits = bits(run.rng());
    cv::Mat cut;
    cut_noise_bits(frame, noise_bits, cut);
    FeatureExtractor cutting(grid, noise_bits);
    EXPECT_EQ(cutting.noise_bits(), noise_bits);
    ASSERT_EQ(first_difference(cutting.extract(frame), test::reference_features(cut, grid)), "")
        << "iteration " << i << ", noise bits " << noise_bits;
  }
}

TEST(FeatureExtractor, ReadsFramesThatAreViewsIntoLargerImages) {
  test::PropertyRun run(20);
  const FeatureGrid grid = FeatureGrid::tiling(33, 18, 3, 2);
  FeatureExtractor extractor(grid);
  for (int i = 0; i < run.iterations(); ++i) {
    const cv::Mat larger = test::random_frame(run.rng(), cv::Size(50, 30));
    const cv::Mat view = larger(cv::Rect(7, 5, 33, 18));  // not continuous
    ASSERT_FALSE(view.isContinuous());
    ASSERT_EQ(first_difference(extractor.extract(view), test::reference_features(view, grid)), "")
        << "iteration " << i;
  }
}

TEST(FeatureExtractor, ReplacesImagesOfAnotherGridAndReusesImagesOfItsOwn) {
  const FeatureGrid grid = FeatureGrid::tiling(22, 18, 2, 2);
  FeatureExtractor extractor(grid);
  const cv::Mat frame(18, 22, CV_8UC1, cv::Scalar::all(7));

  FeatureImages other(FeatureGrid::tiling(4, 4, 1, 1));
  extractor.extract(frame, other);
  EXPECT_EQ(other.grid, grid);
  EXPECT_EQ(other[Feature::kAverage].size(), cv::Size(2, 2));
  EXPECT_EQ(other[Feature::kAverage].at<std::uint8_t>(1, 1), 7);

  FeatureImages own(grid);
  const std::uint8_t* before = own[Feature::kEdgeCount].data;
  extractor.extract(frame, own);
  EXPECT_EQ(own[Feature::kEdgeCount].data, before);
  EXPECT_EQ(own[Feature::kAverage].at<std::uint8_t>(0, 1), 7);
}

TEST(FeatureImages, CloneDoesNotShareThePlanes) {
  FeatureImages original(FeatureGrid::tiling(4, 2, 2, 1));
  original[Feature::kSpan].at<std::uint8_t>(0, 1) = 9;
  const FeatureImages shared = original;
  const FeatureImages copy = original.clone();
  original[Feature::kSpan].at<std::uint8_t>(0, 1) = 10;
  EXPECT_EQ(shared[Feature::kSpan].at<std::uint8_t>(0, 1), 10);  // cv::Mat shares on copy
  EXPECT_EQ(copy[Feature::kSpan].at<std::uint8_t>(0, 1), 9);
  EXPECT_EQ(copy.grid, original.grid);
  EXPECT_EQ(feature_name(Feature::kEdgeCount), "edge_count");
}

TEST(FeatureExtractor, RefusesBadNoiseBits) {
  test::expect_invalid_argument([] { FeatureExtractor extractor(FeatureGrid{}, 8); },
                                {"noise_bits", "8", "expected 0..7"});
  test::expect_invalid_argument([] { FeatureExtractor extractor(FeatureGrid{}, -1); },
                                {"noise_bits", "-1"});
}

TEST(FeatureExtractor, RefusesWrongFrames) {
  FeatureExtractor extractor;
  test::expect_invalid_argument([&] { static_cast<void>(extractor.extract(cv::Mat())); },
                                {"frame", "expected CV_8UC1 704 x 576 px", "an empty image"});
  test::expect_invalid_argument(
      [&] { static_cast<void>(extractor.extract(cv::Mat(576, 704, CV_8UC3))); },
      {"frame", "expected CV_8UC1 704 x 576 px", "got CV_8UC3 704 x 576 px"});
  test::expect_invalid_argument(
      [&] { static_cast<void>(extractor.extract(cv::Mat(576, 704, CV_16UC1))); },
      {"expected CV_8UC1 704 x 576 px", "got CV_16UC1 704 x 576 px"});
  test::expect_invalid_argument(
      [&] { static_cast<void>(extractor.extract(cv::Mat(576, 705, CV_8UC1))); },
      {"expected CV_8UC1 704 x 576 px", "got CV_8UC1 705 x 576 px"});
  test::expect_invalid_argument(
      [&] { static_cast<void>(extractor.extract(cv::Mat(575, 704, CV_8UC1))); },
      {"got CV_8UC1 704 x 575 px"});
}

}  // namespace
}  // namespace safecell
