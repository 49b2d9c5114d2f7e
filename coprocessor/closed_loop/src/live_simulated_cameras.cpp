#include "safecell/closed_loop/live_simulated_cameras.hpp"

#include <stdexcept>

#include "safecell/service/sensing_service.hpp"

namespace safecell {

LiveSimulatedCameras::LiveSimulatedCameras(SimulatedCell& cell, SceneAt scene_at)
    : cell_(cell), scene_at_(std::move(scene_at)) {
  if (!scene_at_) throw std::invalid_argument("LiveSimulatedCameras: no scene");
}

FrameSet LiveSimulatedCameras::acquire() {
  const std::uint64_t exposure_ns = steady_now_ns();
  scene_ = scene_at_(exposure_ns);
  ++sets_;
  const double exposure_s = static_cast<double>(exposure_ns) * 1e-9;
  frames_ = cell_.render(scene_, sets_, exposure_s, &object_ids_);
  FrameSet set;
  set.index = sets_;
  for (std::size_t c = 0; c < frames_.size(); ++c) {
    CameraFrame frame;
    frame.camera = cell_.camera(c).name();
    frame.image = frames_[c];
    frame.counter = sets_;
    frame.exposure_s = exposure_s;
    frame.stamp_source = StampSource::kBackend;
    set.frames.push_back(std::move(frame));
  }
  return set;
}

}  // namespace safecell
