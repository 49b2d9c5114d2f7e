#pragma once
// The cameras of the simulated cell as camera sources. All of them share one rig; frame k of
// the rig is the scene at time k * frame_period_s rendered for every camera at once. A camera's
// grab() asks the rig for its next frame k: the first camera to ask renders all cameras (the
// moment of exposure), the others find frame k already there, so grabbing all cameras of a set
// renders the cell once; retrieve() hands the camera's picture out. A camera that runs ahead of
// the others makes the rig render again (correct, only slower). Not thread-safe.

#include <cstdint>
#include <exception>
#include <functional>
#include <memory>
#include <vector>

#include "safecell/acquisition/camera_source.hpp"
#include "safecell/sim/simulated_cell.hpp"

namespace safecell {

class SimulatedCameraRig {
 public:
  using SceneAt = std::function<SimScene(double time_s)>;

  // Throws std::invalid_argument unless frame_period_s is finite and > 0 and scene_at is set.
  SimulatedCameraRig(SimulatedCell cell, SceneAt scene_at, double frame_period_s);

  [[nodiscard]] const SimulatedCell& cell() const { return cell_; }
  [[nodiscard]] double time_s(std::uint64_t frame_index) const {
    return static_cast<double>(frame_index) * frame_period_s_;
  }
  // How often the cell was rendered (all cameras each time).
  [[nodiscard]] std::uint64_t renders() const { return renders_; }

  // Frame `frame_index` of every camera, rendered now unless it is the frame rendered last.
  const std::vector<cv::Mat>& frames(std::uint64_t frame_index);

 private:
  SimulatedCell cell_;
  SceneAt scene_at_;
  double frame_period_s_;
  std::vector<cv::Mat> frames_;
  std::uint64_t frame_index_ = 0;  // of frames_, when renders_ > 0
  std::uint64_t renders_ = 0;
};

class SimulatedCameraSource final : public CameraSource {
 public:
  // Throws std::out_of_range for a camera index the rig's cell does not have.
  SimulatedCameraSource(std::shared_ptr<SimulatedCameraRig> rig, std::size_t camera_index);

  [[nodiscard]] const std::string& name() const override;
  [[nodiscard]] cv::Size frame_size() const override;

  // Renders (through the rig) the camera's next frame; a scene or render failure is kStopped.
  HealthReport grab() override;
  HealthReport retrieve(SourceFrame& frame) override;

 private:
  HealthReport failure(std::uint64_t frame_index, const std::exception& error) const;

  std::shared_ptr<SimulatedCameraRig> rig_;
  std::size_t camera_index_;
  std::uint64_t frames_grabbed_ = 0;  // the next frame is frame frames_grabbed_ (from 0)
};

// One source per camera of the rig's cell, in the cell's order.
std::vector<std::unique_ptr<CameraSource>> simulated_camera_sources(
    const std::shared_ptr<SimulatedCameraRig>& rig);

}  // namespace safecell
