#pragma once
// Camera faults for a fault campaign, between a frame-set source and the sensing service: chosen
// cameras freeze (the image they showed when the fault began, again and again), are blinded
// (saturated), are knocked (the image shifted by a few pixels) or are unplugged (no frame: the
// view unknown, as a camera that stopped delivering). The service's health checks must find the
// first three on their own; an unplugged camera is reported as the acquisition would.

#include <cstddef>
#include <optional>
#include <vector>

#include "safecell/campaign/fault_class.hpp"
#include "safecell/service/frame_set_source.hpp"

namespace safecell {

class CameraFaultInjector final : public FrameSetSource {
 public:
  explicit CameraFaultInjector(FrameSetSource& source) : source_(source) {}

  // From the next set on, `fault` (a camera class) on the cameras at `cameras` (indices into the
  // frame set). Precondition: site_of(fault) == FaultSite::kCameras.
  void begin(FaultClass fault, std::vector<std::size_t> cameras);
  void end() { fault_.reset(); }

  FrameSet acquire() override;

  // Frames altered so far.
  [[nodiscard]] std::size_t injected() const { return injected_; }

 private:
  FrameSetSource& source_;
  std::optional<FaultClass> fault_;
  std::vector<std::size_t> cameras_;
  std::vector<cv::Mat> frozen_;  // per camera of cameras_: the image it shows while frozen
  std::size_t injected_ = 0;
};

}  // namespace safecell
