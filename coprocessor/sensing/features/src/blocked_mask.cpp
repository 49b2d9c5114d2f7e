#include "safecell/features/blocked_mask.hpp"

#include <algorithm>
#include <cstdint>
#include <cstdlib>
#include <opencv2/core.hpp>
#include <string>

#include "image_checks.hpp"
#include "row_kernels.hpp"

namespace safecell {
namespace {

void check_weights(const FeatureWeights& weights) {
  bool any = false;
  for (const Feature feature : kAllFeatures) {
    const int weight = weights.of(feature);
    if (weight < 0 || weight > kMaxFeatureWeight) {
      throw_invalid_argument(
          "weights." + std::string(feature_name(feature)),
          std::to_string(weight) + ", expected 0.." + std::to_string(kMaxFeatureWeight));
    }
    any = any || weight > 0;
  }
  if (!any) {
    throw_invalid_argument("weights", "all 0, expected a weight > 0 for at least one feature");
  }
}

void check_planes(const FeatureImages& images, std::string_view parameter) {
  const cv::Size size(images.grid.columns(), images.grid.rows());
  for (const Feature feature : kAllFeatures) {
    check_gray_image_of_size(images[feature], size,
                             std::string(parameter) + "." + std::string(feature_name(feature)),
                             "the grid's columns x rows");
  }
}

void check_inputs(const FeatureImages& current, const FeatureImages& reference,
                  const FeatureWeights& weights) {
  check_weights(weights);
  if (reference.grid != current.grid) {
    throw_invalid_argument("reference", "feature grid " + grid_text(reference.grid) +
                                            ", expected the grid of current, " +
                                            grid_text(current.grid));
  }
  check_planes(current, "current");
  check_planes(reference, "reference");
}

// distance[x] += weight * |a[x] - b[x]| for x < count; the whole blocks vectorise (see
// row_kernels.hpp). weight <= 255, so each term fits 16 bits.
void add_weighted_difference(const std::uint8_t* __restrict a, const std::uint8_t* __restrict b,
                             std::uint16_t weight, std::int32_t* __restrict distance, int count) {
  using row_kernels::kBlock;
  const int whole_blocks = count / kBlock * kBlock;
  for (int block = 0; block < whole_blocks; block += kBlock) {
    for (int x = block; x < block + kBlock; ++x) {
      const auto difference =
          static_cast<std::uint8_t>(std::max(a[x], b[x]) - std::min(a[x], b[x]));
      distance[x] += static_cast<std::uint16_t>(weight * difference);
    }
  }
  for (int x = whole_blocks; x < count; ++x) {
    distance[x] += weight * std::abs(a[x] - b[x]);
  }
}

// distance += weight * |current - reference| over one plane.
void add_weighted_plane_difference(const cv::Mat& current, const cv::Mat& reference, int weight,
                                   cv::Mat& distance) {
  for (int row = 0; row < distance.rows; ++row) {
    add_weighted_difference(current.ptr<std::uint8_t>(row), reference.ptr<std::uint8_t>(row),
                            static_cast<std::uint16_t>(weight), distance.ptr<std::int32_t>(row),
                            distance.cols);
  }
}

}  // namespace

int FeatureWeights::of(Feature feature) const {
  switch (feature) {
    case Feature::kAverage:
      return average;
    case Feature::kVariance:
      return variance;
    case Feature::kSpan:
      return span;
    case Feature::kContrast:
      return contrast;
    case Feature::kEdgeCount:
      return edge_count;
  }
  return 0;
}

cv::Mat feature_distance(const FeatureImages& current, const FeatureImages& reference,
                         const FeatureWeights& weights) {
  check_inputs(current, reference, weights);
  cv::Mat distance = cv::Mat::zeros(current.grid.rows(), current.grid.columns(), CV_32SC1);
  for (const Feature feature : kAllFeatures) {
    if (weights.of(feature) == 0) continue;
    add_weighted_plane_difference(current[feature], reference[feature], weights.of(feature),
                                  distance);
  }
  return distance;
}

cv::Mat blocked_mask(const FeatureImages& current, const FeatureImages& reference,
                     const FeatureWeights& weights, int threshold) {
  if (threshold < 0) {
    throw_invalid_argument("threshold", std::to_string(threshold) + ", expected >= 0");
  }
  cv::Mat mask;
  cv::compare(feature_distance(current, reference, weights), cv::Scalar::all(threshold), mask,
              cv::CMP_GT);  // 255 where greater, else 0
  return mask;
}

}  // namespace safecell
