#pragma once
// The last word on each camera's view in a frame set: the acquisition's own verdict (unopened,
// stopped, corrupt, wrong format) and then, for the frames that arrived, the camera's health
// monitor (black, saturated, frozen, lighting change, moved). What comes out is what the rest of
// the pipeline uses: a known view with its image, or an unknown one with the cause.
// A line goes to the log when a camera's view turns unknown, when its cause changes, and when
// it is known again, each naming the camera and the cause; a fault that persists is not
// repeated every frame. Not thread-safe.

#include <functional>
#include <string>
#include <string_view>
#include <vector>

#include "safecell/acquisition/frame_set.hpp"
#include "safecell/cell/cell_model.hpp"
#include "safecell/health/camera_health_monitor.hpp"

namespace safecell {

class CameraViews {
 public:
  using Log = std::function<void(std::string_view line)>;

  // One monitor per camera, in the order of the frame sets' frames. Throws
  // std::invalid_argument when there is no monitor or `log` is empty.
  CameraViews(std::vector<CameraHealthMonitor> monitors, Log log);

  // Checks every frame with a known view and sets the view of each failing one to its health
  // fault. Throws std::invalid_argument when the set's cameras are not the monitors' (count
  // or names), naming both.
  void check(FrameSet& set);

 private:
  void log_change(const CameraFrame& frame, std::size_t index);

  std::vector<CameraHealthMonitor> monitors_;
  Log log_;
  std::vector<CameraFault> last_faults_;  // per camera; kNone before the first set
};

// The views of a cell's cameras: a monitor per camera, in the cell's order, against its reference
// image (the empty cell). Throws std::invalid_argument when the counts differ.
CameraViews camera_views_for(const CellModel& cell, const std::vector<cv::Mat>& references,
                             CameraViews::Log log, const HealthSettings& settings = {});

}  // namespace safecell
