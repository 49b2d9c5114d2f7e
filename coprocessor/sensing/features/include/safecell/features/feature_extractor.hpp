#pragma once
// Computes the feature images (feature_images.hpp) of frames on one feature grid.
//
// One pass over the frame per cell row, in integer arithmetic: each image row is filtered with
// the LoG as it arrives (the filter keeps three rows of state, so the whole frame is filtered
// exactly once), and its pixels and |LoG| are added into per-column sums, sums of squares,
// minima and maxima; at the end of a cell row those columns are summed per cell and scaled. The
// row loops are vectorised (SSE2, and AVX2 where the CPU has it). The results equal the
// definitions in feature_images.hpp exactly, bit for bit (the per-cell divisions by the fixed
// cell size multiply by a rounded reciprocal and then correct in exact integer arithmetic).
//
// Not thread-safe: an extractor holds its scratch rows. Use one per camera and thread. After
// the first frame, extract() into the same FeatureImages allocates nothing.

#include <memory>
#include <opencv2/core/mat.hpp>

#include "safecell/camera/feature_grid.hpp"
#include "safecell/features/feature_images.hpp"

namespace safecell {

class FeatureExtractor {
 public:
  // With noise_bits > 0 the extractor cuts that many low bits off every pixel as it reads it:
  // extract(frame) then equals extract(cut_noise_bits(frame)) with no pass of its own. Throws
  // std::invalid_argument for noise_bits outside 0..kMaxNoiseBits (noise_cut.hpp).
  explicit FeatureExtractor(const FeatureGrid& grid = FeatureGrid{}, int noise_bits = 0);
  ~FeatureExtractor();
  FeatureExtractor(FeatureExtractor&&) noexcept;
  FeatureExtractor& operator=(FeatureExtractor&&) noexcept;
  FeatureExtractor(const FeatureExtractor&) = delete;
  FeatureExtractor& operator=(const FeatureExtractor&) = delete;

  [[nodiscard]] const FeatureGrid& grid() const { return grid_; }
  [[nodiscard]] int noise_bits() const { return noise_bits_; }

  // The feature images of `frame` into `images`, whose planes are reused when they already
  // have the grid's size (then nothing is allocated). Throws std::invalid_argument when the
  // frame is empty, not CV_8UC1, or not of the grid's image size.
  void extract(const cv::Mat& frame, FeatureImages& images);
  [[nodiscard]] FeatureImages extract(const cv::Mat& frame);

 private:
  class Pass;  // the scratch rows and the pass itself (feature_extractor.cpp)

  FeatureGrid grid_;
  int noise_bits_;
  std::unique_ptr<Pass> pass_;
};

}  // namespace safecell
