#pragma once
// Which feature cells differ from the reference: the paper's difference image. The distance of a
// cell is sum over the features f of w_f * |current_f - reference_f| (integer, in feature units);
// a cell is blocked when its distance exceeds the threshold. A weight of 0 leaves a feature out.

#include <opencv2/core/mat.hpp>

#include "safecell/features/feature_images.hpp"

namespace safecell {

// The largest weight: with all five at it a distance stays below 2^19.
inline constexpr int kMaxFeatureWeight = 255;

// Integer weights 0..kMaxFeatureWeight; at least one must be > 0.
struct FeatureWeights {
  int average = 0;
  int variance = 0;
  int span = 0;
  int contrast = 0;
  int edge_count = 0;

  [[nodiscard]] int of(Feature feature) const;
};

// Defaults tuned on the simulated default cell (sensor noise sigma 2): a walking human blocks
// hundreds of cells over the four cameras, a new frame of the empty scene none (the benchmark's
// blocked_cells counters show both). A cell file will override them.
inline constexpr FeatureWeights kDefaultFeatureWeights{2, 1, 1, 0, 1};
inline constexpr int kDefaultBlockedThreshold = 24;

// The distance per cell: CV_32SC1, grid.rows() x grid.columns(). Throws std::invalid_argument
// naming the parameter and its value for a weight outside 0..kMaxFeatureWeight, all weights 0,
// feature images on different grids, or a plane that is not CV_8UC1 of the grid's size.
[[nodiscard]] cv::Mat feature_distance(const FeatureImages& current, const FeatureImages& reference,
                                       const FeatureWeights& weights);

// The blocked mask: CV_8UC1, grid.rows() x grid.columns(), 255 where the distance > threshold
// (blocked), 0 elsewhere (free). Throws as feature_distance(), and for threshold < 0.
[[nodiscard]] cv::Mat blocked_mask(const FeatureImages& current, const FeatureImages& reference,
                                   const FeatureWeights& weights, int threshold);

}  // namespace safecell
