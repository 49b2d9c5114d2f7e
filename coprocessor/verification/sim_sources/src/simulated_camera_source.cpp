#include "safecell/sim_sources/simulated_camera_source.hpp"

#include <cmath>
#include <stdexcept>

namespace safecell {

SimulatedCameraRig::SimulatedCameraRig(SimulatedCell cell, SceneAt scene_at, double frame_period_s)
    : cell_(std::move(cell)), scene_at_(std::move(scene_at)), frame_period_s_(frame_period_s) {
  if (!scene_at_) throw std::invalid_argument("simulated camera rig: no scene function");
  if (!std::isfinite(frame_period_s_) || !(frame_period_s_ > 0.0)) {
    throw std::invalid_argument("simulated camera rig: frame period " +
                                std::to_string(frame_period_s_) + " s is not positive");
  }
}

const std::vector<cv::Mat>& SimulatedCameraRig::frames(std::uint64_t frame_index) {
  if (renders_ == 0 || frame_index != frame_index_) {
    const double time_s = this->time_s(frame_index);
    frames_ = cell_.render(scene_at_(time_s), frame_index, time_s);
    frame_index_ = frame_index;
    ++renders_;
  }
  return frames_;
}

SimulatedCameraSource::SimulatedCameraSource(std::shared_ptr<SimulatedCameraRig> rig,
                                             std::size_t camera_index)
    : rig_(std::move(rig)), camera_index_(camera_index) {
  if (!rig_) throw std::invalid_argument("simulated camera source: no rig");
  if (camera_index_ >= rig_->cell().camera_count()) {
    throw std::out_of_range("simulated camera source: camera " + std::to_string(camera_index_) +
                            " of a cell with " + std::to_string(rig_->cell().camera_count()));
  }
}

const std::string& SimulatedCameraSource::name() const {
  return rig_->cell().camera(camera_index_).name();
}

cv::Size SimulatedCameraSource::frame_size() const {
  const CameraIntrinsics& intrinsics = rig_->cell().camera(camera_index_).intrinsics();
  return {intrinsics.width_px, intrinsics.height_px};
}

HealthReport SimulatedCameraSource::failure(std::uint64_t frame_index,
                                            const std::exception& error) const {
  return camera_fault_report(
      name(), CameraFault::kStopped,
      "simulated frame " + std::to_string(frame_index) + " failed: " + error.what());
}

HealthReport SimulatedCameraSource::grab() {
  try {
    rig_->frames(frames_grabbed_);
  } catch (const std::exception& error) {
    return failure(frames_grabbed_, error);
  }
  ++frames_grabbed_;
  return {};
}

HealthReport SimulatedCameraSource::retrieve(SourceFrame& frame) {
  frame = SourceFrame{};
  if (frames_grabbed_ == 0) {
    return camera_fault_report(name(), CameraFault::kStopped, "retrieve() before any grab()");
  }
  const std::uint64_t frame_index = frames_grabbed_ - 1;
  try {
    frame.image = rig_->frames(frame_index).at(camera_index_);
  } catch (const std::exception& error) {
    return failure(frame_index, error);
  }
  frame.exposure_s = rig_->time_s(frame_index);
  return {};
}

std::vector<std::unique_ptr<CameraSource>> simulated_camera_sources(
    const std::shared_ptr<SimulatedCameraRig>& rig) {
  std::vector<std::unique_ptr<CameraSource>> sources;
  for (std::size_t i = 0; i < rig->cell().camera_count(); ++i) {
    sources.push_back(std::make_unique<SimulatedCameraSource>(rig, i));
  }
  return sources;
}

}  // namespace safecell
