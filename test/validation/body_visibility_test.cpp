// "Visible" from object-id images (VALIDATION.md): half a feature cell front-most, and the reason
// a body is not visible, on hand-drawn images.

#include "safecell/validation/body_visibility.hpp"

#include <gtest/gtest.h>

namespace safecell {
namespace {

// 4 x 3 feature cells of 10 x 8 pixels.
const FeatureGrid kGrid = FeatureGrid::tiling(40, 24, 4, 3);
const BodyCode kHuman = body_code(BodyKind::kHuman, 0);

cv::Mat background() { return cv::Mat(24, 40, CV_16UC1, cv::Scalar(0)); }
cv::Mat nothing() { return cv::Mat(24, 40, CV_8UC1, cv::Scalar(0)); }

TEST(BodyVisibility, HalfAFeatureCellFrontMostIsVisible) {
  cv::Mat ids = background();
  // 40 of the 80 pixels of feature cell (1, 1): exactly half.
  ids(cv::Rect(10, 8, 5, 8)).setTo(kHuman);
  FeatureMask visible = front_most_cells(ids, kHuman, kGrid);
  EXPECT_EQ(visible.count(), 1U);
  EXPECT_TRUE(visible.test(1, 1));
  // One pixel fewer is not enough, even with more spread over two cells.
  ids = background();
  ids(cv::Rect(10, 8, 5, 8)).setTo(kHuman);
  ids.at<BodyCode>(8, 10) = 0;
  ids(cv::Rect(0, 0, 4, 8)).setTo(kHuman);  // 32 pixels of cell (0, 0)
  EXPECT_FALSE(front_most_cells(ids, kHuman, kGrid).any());
  // Another body's pixels do not count.
  ids = background();
  ids(cv::Rect(10, 8, 10, 8)).setTo(body_code(BodyKind::kHuman, 1));
  EXPECT_FALSE(front_most_cells(ids, kHuman, kGrid).any());
}

TEST(BodyVisibility, ImagesOfAnotherSizeOrTypeAreRefused) {
  EXPECT_THROW((void)front_most_cells(cv::Mat(24, 41, CV_16UC1), kHuman, kGrid),
               std::invalid_argument);
  EXPECT_THROW((void)front_most_cells(nothing(), kHuman, kGrid), std::invalid_argument);
  EXPECT_THROW((void)why_not_visible(background(), background(), kHuman, kGrid),
               std::invalid_argument);
}

TEST(BodyVisibility, TheReasonIsWhatHidesMostOfTheBody) {
  cv::Mat alone = nothing();
  EXPECT_EQ(why_not_visible(background(), alone, kHuman, kGrid), UnseenReason::kOutsideViews);
  alone(cv::Rect(0, 0, 3, 3)).setTo(255);  // 9 pixels: not half a cell even unhidden
  EXPECT_EQ(why_not_visible(background(), alone, kHuman, kGrid), UnseenReason::kTooSmall);

  alone = nothing();
  alone(cv::Rect(10, 8, 10, 8)).setTo(255);  // the whole of cell (1, 1)
  cv::Mat ids = background();
  ids(cv::Rect(10, 8, 10, 5)).setTo(body_code(BodyKind::kRobot));
  ids(cv::Rect(10, 13, 10, 3)).setTo(body_code(BodyKind::kStaticObstacle, 0));
  EXPECT_EQ(why_not_visible(ids, alone, kHuman, kGrid), UnseenReason::kHiddenByRobot);
  ids(cv::Rect(10, 8, 10, 5)).setTo(body_code(BodyKind::kObject, 2));
  ids(cv::Rect(10, 8, 10, 2)).setTo(kHuman);  // its own visible part counts for nothing
  EXPECT_EQ(why_not_visible(ids, alone, kHuman, kGrid), UnseenReason::kHiddenByStaticObstacle);
  ids(cv::Rect(10, 10, 10, 6)).setTo(body_code(BodyKind::kObject, 2));
  EXPECT_EQ(why_not_visible(ids, alone, kHuman, kGrid), UnseenReason::kHiddenByOtherBody);
  for (std::size_t r = 0; r < kUnseenReasonCount; ++r) {
    EXPECT_STRNE(to_string(static_cast<UnseenReason>(r)), "unknown");
  }
}

}  // namespace
}  // namespace safecell
