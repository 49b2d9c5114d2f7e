#include "safecell/acquisition/frame_set.hpp"

#include <algorithm>
#include <stdexcept>

namespace safecell {

std::size_t FrameSet::known_count() const {
  return static_cast<std::size_t>(
      std::count_if(frames.begin(), frames.end(), [](const CameraFrame& f) { return f.known(); }));
}

FrameSet frame_set_exposed_at(const std::vector<std::string>& cameras,
                              const std::vector<cv::Mat>& images, std::uint64_t index,
                              double exposure_s) {
  if (cameras.size() != images.size()) {
    throw std::invalid_argument("frame set: " + std::to_string(images.size()) + " images for " +
                                std::to_string(cameras.size()) + " cameras");
  }
  FrameSet set;
  set.index = index;
  for (std::size_t c = 0; c < images.size(); ++c) {
    CameraFrame frame;
    frame.camera = cameras[c];
    frame.image = images[c];
    frame.counter = index;
    frame.exposure_s = exposure_s;
    frame.stamp_source = StampSource::kBackend;
    set.frames.push_back(std::move(frame));
  }
  return set;
}

}  // namespace safecell
