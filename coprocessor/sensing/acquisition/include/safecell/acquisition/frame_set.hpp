#pragma once
// The frames of all cameras taken together in one cycle: one entry per camera, always, in the
// order of the acquirer's sources. A camera that delivered nothing usable is there too, its view
// unknown with the cause; the rest of the pipeline treats an unknown view as seeing everything.

#include <cstdint>
#include <opencv2/core.hpp>
#include <string>
#include <vector>

#include "safecell/health/camera_fault.hpp"

namespace safecell {

// Where a frame's exposure time came from.
enum class StampSource {
  kBackend,    // the backend's own clock (see SourceFrame::exposure_s)
  kGrabClock,  // std::chrono::steady_clock when the frame was grabbed
};

struct CameraFrame {
  std::string camera;  // the camera's name
  // CV_8UC1 of the camera's size while the view is known. Empty when the camera delivered
  // nothing usable; after a health fault (CameraViews) the frame stays for pictures and logs.
  cv::Mat image;
  // Frames this camera has delivered so far, this one included (1 for the first); a cycle in
  // which it delivered none keeps the last count.
  std::uint64_t counter = 0;
  // See stamp_source. When the camera delivered no frame: the time of the attempt (kGrabClock).
  double exposure_s = 0.0;
  StampSource stamp_source = StampSource::kGrabClock;
  HealthReport view;  // healthy(): the view is known; otherwise the cause, naming the camera
  // Frames the camera's source passed over just before this one (SourceFrame::passed_over).
  std::uint64_t passed_over = 0;

  [[nodiscard]] bool known() const { return view.healthy(); }
};

struct FrameSet {
  std::uint64_t index = 0;  // sets acquired so far, this one included
  std::vector<CameraFrame> frames;

  [[nodiscard]] std::size_t known_count() const;
};

// A set of frames exposed together at exposure_s by the source's own clock (kBackend), every view
// known: one frame per camera, `images` in the order of `cameras`, each counted `index`.
// Throws std::invalid_argument when the counts differ.
FrameSet frame_set_exposed_at(const std::vector<std::string>& cameras,
                              const std::vector<cv::Mat>& images, std::uint64_t index,
                              double exposure_s);

}  // namespace safecell
