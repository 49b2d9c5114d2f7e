#include "safecell/closed_loop/live_simulated_cameras.hpp"

#include <stdexcept>

#include "safecell/service/sensing_service.hpp"

namespace safecell {

LiveSimulatedCameras::LiveSimulatedCameras(SimulatedCell& cell, SceneAt scene_at,
                                           ExposureClock clock)
    : cell_(cell), scene_at_(std::move(scene_at)), clock_(std::move(clock)) {
  if (!scene_at_) throw std::invalid_argument("LiveSimulatedCameras: no scene");
  for (std::size_t c = 0; c < cell_.camera_count(); ++c) cameras_.push_back(cell_.camera(c).name());
}

FrameSet LiveSimulatedCameras::acquire() {
  const std::uint64_t exposure_ns = clock_ ? clock_() : steady_now_ns();
  scene_ = scene_at_(exposure_ns);
  ++sets_;
  const double exposure_s = static_cast<double>(exposure_ns) * 1e-9;
  frames_ = cell_.render(scene_, sets_, exposure_s, &object_ids_);
  return frame_set_exposed_at(cameras_, frames_, sets_, exposure_s);
}

}  // namespace safecell
