#include "safecell/closed_loop/replayed_frame_sets.hpp"

#include <stdexcept>

#include "safecell/service/sensing_service.hpp"

namespace safecell {

ReplayedFrameSets::ReplayedFrameSets(std::vector<std::string> cameras,
                                     std::vector<std::vector<cv::Mat>> sets)
    : cameras_(std::move(cameras)), sets_(std::move(sets)) {
  if (sets_.empty()) throw std::invalid_argument("ReplayedFrameSets: no frame set");
  for (std::size_t s = 0; s < sets_.size(); ++s) {
    if (sets_[s].size() != cameras_.size()) {
      throw std::invalid_argument("ReplayedFrameSets: set " + std::to_string(s) + " has " +
                                  std::to_string(sets_[s].size()) + " frames for " +
                                  std::to_string(cameras_.size()) + " cameras");
    }
  }
}

FrameSet ReplayedFrameSets::acquire() {
  const double exposure_s = static_cast<double>(steady_now_ns()) * 1e-9;
  const std::vector<cv::Mat>& frames = sets_[handed_out_ % sets_.size()];
  ++handed_out_;
  return frame_set_exposed_at(cameras_, frames, handed_out_, exposure_s);
}

}  // namespace safecell
