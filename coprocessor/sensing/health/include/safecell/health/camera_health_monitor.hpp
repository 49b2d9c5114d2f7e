#pragma once
// Watches one camera's frames for the faults of SAFETY.md. A frame that fails any check makes the
// camera's view unknown for that cycle (the pipeline then counts it as seeing everything); the
// report names the cause and the measured figure. One monitor per camera; not thread-safe.

#include <opencv2/core.hpp>
#include <string>

#include "safecell/health/camera_fault.hpp"

namespace safecell {

struct HealthSettings {
  // A live sensor's frames differ by its noise: a mean |frame - previous frame| below this
  // floor (gray levels) for `frozen_frames` frames in a row means the picture stopped.
  double dark_noise_floor = 0.25;
  int frozen_frames = 3;
  double black_mean_level = 10.0;   // mean gray below this: black
  double saturated_fraction = 0.5;  // this share of pixels at 250 or more: saturated
  double lighting_change = 0.25;    // mean brightness off the reference's by this share
  double max_shift_px = 3.0;        // image shift against the reference (phase correlation)
};

class CameraHealthMonitor {
 public:
  // reference: the camera's reference image (CV_8UC1), the empty cell as it should look.
  // Throws std::invalid_argument for an empty or non-gray reference or absurd settings.
  CameraHealthMonitor(std::string camera_name, const cv::Mat& reference,
                      const HealthSettings& settings = {});

  // Checks one frame, in the order format, black, saturated, frozen, lighting, alignment.
  HealthReport check(const cv::Mat& frame);

  const std::string& camera_name() const { return camera_name_; }

 private:
  HealthReport fault(CameraFault fault, const std::string& detail) const;
  cv::Point2d shift_against_reference(const cv::Mat& frame) const;

  std::string camera_name_;
  HealthSettings settings_;
  cv::Mat reference_;
  double reference_mean_ = 0.0;
  cv::Mat reference_small_;  // float, downscaled, for the phase correlation
  cv::Mat window_;           // Hanning window of that size
  cv::Mat previous_;
  int still_frames_ = 0;
};

}  // namespace safecell
