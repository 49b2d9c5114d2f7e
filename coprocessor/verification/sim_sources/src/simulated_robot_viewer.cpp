#include "safecell/sim_sources/simulated_robot_viewer.hpp"

#include <stdexcept>
#include <string>

#include "safecell/features/blocked_mask.hpp"

namespace safecell {

SimulatedRobotViewer::SimulatedRobotViewer(SimulatedCell& sim, const CellModel& cell,
                                           const std::vector<cv::Mat>& reference_frames)
    : sim_(sim), cell_(cell), extractor_(cell.feature_grid) {
  if (reference_frames.size() != sim.camera_count()) {
    throw std::invalid_argument(std::to_string(reference_frames.size()) + " reference frames for " +
                                std::to_string(sim.camera_count()) + " cameras");
  }
  for (const cv::Mat& frame : reference_frames) references_.push_back(extractor_.extract(frame));
}

std::vector<FeatureMask> SimulatedRobotViewer::operator()(const std::vector<double>& q) {
  const std::vector<cv::Mat> frames = sim_.render(SimScene{q, {}}, ++frame_index_, 0.0);
  std::vector<FeatureMask> masks;
  masks.reserve(frames.size());
  for (std::size_t camera = 0; camera < frames.size(); ++camera) {
    masks.push_back(FeatureMask::from_image(blocked_mask(extractor_.extract(frames[camera]),
                                                         references_[camera], cell_.feature_weights,
                                                         cell_.blocked_threshold)));
  }
  return masks;
}

}  // namespace safecell
