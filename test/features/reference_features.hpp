#pragma once
// The slow, obvious feature images: every cell straight from the definitions in
// feature_images.hpp, pixel by pixel, the LoG from its 5 x 5 kernel at every pixel with clamped
// coordinates, the variance from pairwise differences. The oracle for FeatureExtractor.

#include <opencv2/core/mat.hpp>

#include "safecell/camera/feature_grid.hpp"
#include "safecell/features/feature_images.hpp"

namespace safecell::test {

// 16 x the LoG at (x, y): the kernel of feature_images.hpp over the frame, edges replicated.
int reference_log16(const cv::Mat& frame, int x, int y);

FeatureImages reference_features(const cv::Mat& frame, const FeatureGrid& grid);

}  // namespace safecell::test
