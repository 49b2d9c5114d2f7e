#include "safecell/features/feature_images.hpp"

namespace safecell {

std::string_view feature_name(Feature feature) {
  switch (feature) {
    case Feature::kAverage:
      return "average";
    case Feature::kVariance:
      return "variance";
    case Feature::kSpan:
      return "span";
    case Feature::kContrast:
      return "contrast";
    case Feature::kEdgeCount:
      return "edge_count";
  }
  return "unknown feature";
}

FeatureImages::FeatureImages(const FeatureGrid& feature_grid) : grid(feature_grid) {
  for (cv::Mat& plane : planes) plane = cv::Mat::zeros(grid.rows(), grid.columns(), CV_8UC1);
}

FeatureImages FeatureImages::clone() const {
  FeatureImages copy(grid);
  for (std::size_t f = 0; f < kFeatureCount; ++f) copy.planes[f] = planes[f].clone();
  return copy;
}

}  // namespace safecell
