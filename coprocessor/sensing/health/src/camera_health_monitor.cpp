#include "safecell/health/camera_health_monitor.hpp"

#include <cmath>
#include <iomanip>
#include <opencv2/imgproc.hpp>
#include <sstream>
#include <stdexcept>

namespace safecell {
namespace {

// Alignment is measured at a quarter of the resolution: fast, and a shift of a few pixels at
// full size still shows (an eighth measured a 3.4 px shift as 2.4 px: too coarse). In single
// precision: the phase correlation of 176 x 144 pixels takes about half the time of doubles,
// and the peak's sub-pixel position needs no more digits.
constexpr double kAlignmentScale = 0.25;

cv::Mat small_float(const cv::Mat& frame) {
  cv::Mat small;
  cv::resize(frame, small, cv::Size(), kAlignmentScale, kAlignmentScale, cv::INTER_AREA);
  cv::Mat as_float;
  small.convertTo(as_float, CV_32F);
  return as_float;
}

std::string figure(const char* what, double value, const char* limit_text, double limit) {
  std::ostringstream text;
  text << std::fixed << std::setprecision(2) << what << ' ' << value << ' ' << limit_text << ' '
       << limit;
  return text.str();
}

}  // namespace

CameraHealthMonitor::CameraHealthMonitor(std::string camera_name, const cv::Mat& reference,
                                         const HealthSettings& settings)
    : camera_name_(std::move(camera_name)), settings_(settings), reference_(reference.clone()) {
  if (reference_.empty() || reference_.type() != CV_8UC1) {
    throw std::invalid_argument("camera '" + camera_name_ +
                                "': the health monitor needs an 8-bit gray reference image");
  }
  if (!(settings_.dark_noise_floor >= 0.0) || settings_.frozen_frames < 1 ||
      !(settings_.saturated_fraction > 0.0 && settings_.saturated_fraction <= 1.0) ||
      !(settings_.lighting_change > 0.0) || !(settings_.max_shift_px > 0.0)) {
    throw std::invalid_argument("camera '" + camera_name_ + "': absurd health settings");
  }
  reference_mean_ = cv::mean(reference_)[0];
  reference_small_ = small_float(reference_);
  cv::createHanningWindow(window_, reference_small_.size(), CV_32F);
}

HealthReport CameraHealthMonitor::fault(CameraFault fault, const std::string& detail) const {
  return camera_fault_report(camera_name_, fault, detail);
}

cv::Point2d CameraHealthMonitor::shift_against_reference(const cv::Mat& frame) const {
  return cv::phaseCorrelate(reference_small_, small_float(frame), window_) / kAlignmentScale;
}

HealthReport CameraHealthMonitor::check(const cv::Mat& frame) {
  if (frame.empty() || frame.type() != CV_8UC1 || frame.size() != reference_.size()) {
    std::ostringstream detail;
    detail << "got " << frame.cols << " x " << frame.rows << " of type " << frame.type()
           << ", expected 8-bit gray " << reference_.cols << " x " << reference_.rows;
    previous_.release();
    return fault(CameraFault::kWrongFormat, detail.str());
  }
  const double mean = cv::mean(frame)[0];
  if (mean < settings_.black_mean_level) {
    return fault(CameraFault::kBlack, figure("mean", mean, "below", settings_.black_mean_level));
  }
  const double saturated = cv::countNonZero(frame >= 250) / static_cast<double>(frame.total());
  if (saturated >= settings_.saturated_fraction) {
    return fault(CameraFault::kSaturated,
                 figure("share at 250+", saturated, "reaches", settings_.saturated_fraction));
  }

  const bool has_previous = !previous_.empty();
  const double change =
      has_previous ? cv::norm(frame, previous_, cv::NORM_L1) / static_cast<double>(frame.total())
                   : 0.0;
  frame.copyTo(previous_);
  still_frames_ = has_previous && change < settings_.dark_noise_floor ? still_frames_ + 1 : 0;
  if (still_frames_ >= settings_.frozen_frames) {
    return fault(CameraFault::kFrozen, figure("mean frame change", change, "below noise floor",
                                              settings_.dark_noise_floor));
  }

  const double relative = std::abs(mean - reference_mean_) / std::max(reference_mean_, 1.0);
  if (relative > settings_.lighting_change) {
    return fault(CameraFault::kLightingChange, figure("brightness off the reference by", relative,
                                                      "beyond", settings_.lighting_change));
  }
  const cv::Point2d shift = shift_against_reference(frame);
  const double shift_px = std::hypot(shift.x, shift.y);
  if (shift_px > settings_.max_shift_px) {
    return fault(CameraFault::kMoved, figure("shift against the reference [px]", shift_px, "beyond",
                                             settings_.max_shift_px));
  }
  return HealthReport{};
}

}  // namespace safecell
