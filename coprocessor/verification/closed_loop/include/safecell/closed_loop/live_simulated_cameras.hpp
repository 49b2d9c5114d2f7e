#pragma once
// The simulated cell's cameras, for a closed loop with a controller process: a frame set is
// exposed at the moment acquire() is called (the coprocessor's steady clock, or the clock given),
// showing the scene of that moment: the robot where the controller's joint stream (or the
// simulation's truth) puts it, and the people where the scenario has them. It keeps the last scene
// and the renderer's object-id images, for the ground truth.

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "safecell/service/frame_set_source.hpp"
#include "safecell/sim/simulated_cell.hpp"

namespace safecell {

class LiveSimulatedCameras final : public FrameSetSource {
 public:
  // The scene at an exposure (steady-clock nanoseconds).
  using SceneAt = std::function<SimScene(std::uint64_t exposure_ns)>;

  // The exposure's time (nanoseconds); the steady clock's now when empty. The closed-loop
  // validation passes its simulated clock.
  using ExposureClock = std::function<std::uint64_t()>;

  LiveSimulatedCameras(SimulatedCell& cell, SceneAt scene_at, ExposureClock clock = {});

  FrameSet acquire() override;

  [[nodiscard]] const SimScene& last_scene() const { return scene_; }
  [[nodiscard]] const std::vector<cv::Mat>& last_frames() const { return frames_; }
  [[nodiscard]] const std::vector<cv::Mat>& last_object_ids() const { return object_ids_; }

 private:
  SimulatedCell& cell_;
  SceneAt scene_at_;
  ExposureClock clock_;
  std::vector<std::string> cameras_;  // the cell's camera names, in order
  std::uint64_t sets_ = 0;
  SimScene scene_;
  std::vector<cv::Mat> frames_;
  std::vector<cv::Mat> object_ids_;
};

}  // namespace safecell
