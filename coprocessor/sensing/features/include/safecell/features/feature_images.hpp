#pragma once
// The feature images of one frame: per feature cell of the grid, the paper's five features, each
// an integer 0..255. The scaling of every feature is fixed (never per image), so the feature
// images of frames taken hours apart stay comparable; values beyond the range are clamped.
//
// With n the cell's pixel count, over the cell's (noise-cut) pixels p:
// - average    = round(sum(p) / n), ties up: (2 sum + n) / (2 n).
// - variance   = min(255, floor(var / kVarianceDivisor)), var = the population variance
//                (n sum(p^2) - sum(p)^2) / n^2 in gray levels^2; 255 from a standard deviation
//                of 64 up.
// - span       = max(p) - min(p).
// - contrast   = round(255 * span / (max + min)), ties up; 0 when max + min = 0.
// - edge count = min(255, floor(sum(|LoG|) / (n * kEdgeCountDivisor))). LoG is the frame
//                filtered with the 5 x 5 integer kernel K = B * L (B: the binomial [1 2 1]^T
//                [1 2 1], a Gaussian of sigma = 1/sqrt(2) px, unnormalised (x16); L: the
//                4-neighbour Laplacian, centre +4), the frame's edges replicated (OpenCV's
//                BORDER_REPLICATE):
//                     0 -1 -2 -1  0
//                    -1  0  2  0 -1
//                    -2  2  8  2 -2
//                    -1  0  2  0 -1
//                     0 -1 -2 -1  0
//                so |LoG| is 16x the gray-level LoG, at most 16 * 255 = 4080. The feature is the
//                mean |LoG| over the cell / 4: a straight step edge of height h across a cell
//                gives 4 h / (cell width); sensor noise of sigma 2 about 4; 255 from a mean |LoG|
//                of 1020 (fine texture of full contrast).
//
// Layout: planar, one CV_8UC1 image of grid.rows() x grid.columns() per feature (a plane reads
// like a grayscale picture of that feature, and the distance runs plane by plane). cv::Mat
// shares its data on copy: copying FeatureImages shares the planes, clone() does not.

#include <array>
#include <cstddef>
#include <opencv2/core/mat.hpp>
#include <string_view>

#include "safecell/camera/feature_grid.hpp"

namespace safecell {

enum class Feature { kAverage, kVariance, kSpan, kContrast, kEdgeCount };

inline constexpr std::size_t kFeatureCount = 5;
inline constexpr std::array<Feature, kFeatureCount> kAllFeatures{
    Feature::kAverage, Feature::kVariance, Feature::kSpan, Feature::kContrast, Feature::kEdgeCount};

// Gray levels^2 of population variance per step of the variance feature.
inline constexpr int kVarianceDivisor = 16;
// Units of |LoG| (16x gray levels, see above) per pixel per step of the edge-count feature.
inline constexpr int kEdgeCountDivisor = 4;

// "average", "variance", "span", "contrast", "edge_count".
[[nodiscard]] std::string_view feature_name(Feature feature);

struct FeatureImages {
  // All planes zero, of the grid's size.
  explicit FeatureImages(const FeatureGrid& feature_grid = FeatureGrid{});

  [[nodiscard]] cv::Mat& operator[](Feature feature) {
    return planes[static_cast<std::size_t>(feature)];
  }
  [[nodiscard]] const cv::Mat& operator[](Feature feature) const {
    return planes[static_cast<std::size_t>(feature)];
  }
  // A deep copy: the planes are not shared.
  [[nodiscard]] FeatureImages clone() const;

  FeatureGrid grid;
  // Indexed by Feature; each CV_8UC1, grid.rows() x grid.columns(), row-major like the grid.
  std::array<cv::Mat, kFeatureCount> planes;
};

}  // namespace safecell
