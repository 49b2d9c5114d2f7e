#pragma once
// The simulated cell standing in for the real robot and cameras when tables are recorded
// (recorded_silhouettes.hpp): the robot alone at a configuration, rendered by every camera, and
// its blocked feature cells against the reference images - the paper's difference images.

#include <opencv2/core/mat.hpp>
#include <vector>

#include "safecell/cell/cell_model.hpp"
#include "safecell/features/feature_extractor.hpp"
#include "safecell/features/feature_mask.hpp"
#include "safecell/sim/simulated_cell.hpp"

namespace safecell {

class SimulatedRobotViewer {
 public:
  // Keeps a reference to `sim` and `cell`. reference_frames: per camera, CV_8UC1 of its size
  // (simulated_reference.hpp). Throws std::invalid_argument for a count other than the cameras'.
  SimulatedRobotViewer(SimulatedCell& sim, const CellModel& cell,
                       const std::vector<cv::Mat>& reference_frames);

  // Not thread-safe (one simulated cell renders at a time).
  std::vector<FeatureMask> operator()(const std::vector<double>& q);

 private:
  SimulatedCell& sim_;
  const CellModel& cell_;
  FeatureExtractor extractor_;
  std::vector<FeatureImages> references_;
  std::uint64_t frame_index_ = 0;
};

}  // namespace safecell
