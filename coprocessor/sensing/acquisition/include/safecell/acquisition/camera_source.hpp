#pragma once
// One camera as the acquisition sees it: a port with backends for OpenCV capture devices and
// streams, folders of image files and the simulated cell.
//
// A frame is taken in two phases so that the frames of all cameras are exposed as close together
// as the backends allow: grab() latches the next frame and does nothing slow (no decoding, no
// conversion); retrieve() then hands out the frame grab() latched. FrameSetAcquirer grabs every
// camera before it retrieves any. A source never throws from grab() or retrieve(): what goes
// wrong comes back as a fault report naming the camera. Not thread-safe.

#include <cstdint>
#include <opencv2/core.hpp>
#include <optional>
#include <string>

#include "safecell/health/camera_fault.hpp"

namespace safecell {

// A frame as a backend delivers it; FrameSetAcquirer checks its size and format.
struct SourceFrame {
  cv::Mat image;  // 8-bit gray, BGR or BGRA (colour is converted to gray); anything else is wrong
  // When the backend knows when the frame was exposed: in seconds on the backend's own clock
  // (media time of a video file, the sidecar CSV of an image folder, simulated time).
  std::optional<double> exposure_s;
  std::string origin;  // where the frame came from (a file), for error messages; may be empty
  // Frames the source passed over since the one it delivered before this (a recording played
  // live that fell behind its pace); 0 for a source that hands out every frame.
  std::uint64_t passed_over = 0;
};

class CameraSource {
 public:
  CameraSource() = default;
  virtual ~CameraSource() = default;
  CameraSource(const CameraSource&) = delete;
  CameraSource& operator=(const CameraSource&) = delete;
  CameraSource(CameraSource&&) = delete;
  CameraSource& operator=(CameraSource&&) = delete;

  // The camera's name, as in the cell file.
  [[nodiscard]] virtual const std::string& name() const = 0;
  // The size every frame must have (the camera's calibrated image size).
  [[nodiscard]] virtual cv::Size frame_size() const = 0;

  // Latches the next frame. Healthy, or kUnavailable (the camera could not be opened) or
  // kStopped (no next frame: the device stopped, the file or folder is exhausted).
  virtual HealthReport grab() = 0;
  // The frame the last successful grab() latched, into `frame`. Healthy, or kStopped or
  // kCorruptFrame (the frame could not be decoded).
  virtual HealthReport retrieve(SourceFrame& frame) = 0;
};

}  // namespace safecell
