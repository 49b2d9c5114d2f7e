#include "safecell/acquisition/video_capture_source.hpp"

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <opencv2/videoio.hpp>

namespace safecell {
namespace {

#if defined(__linux__)
constexpr int kDeviceApi = cv::CAP_V4L2;
#else
constexpr int kDeviceApi = cv::CAP_ANY;
#endif

bool all_digits(const std::string& text) {
  return !text.empty() &&
         std::all_of(text.begin(), text.end(), [](unsigned char c) { return std::isdigit(c); });
}

}  // namespace

VideoCaptureSource::Kind VideoCaptureSource::kind_of(const std::string& spec) {
  if (all_digits(spec) && spec.size() < 6) return Kind::kDevice;
  if (spec.find('!') != std::string::npos) return Kind::kPipeline;
  if (spec.find("://") != std::string::npos) return Kind::kStream;
  return Kind::kFile;
}

VideoCaptureSource::VideoCaptureSource(std::string camera_name, cv::Size frame_size,
                                       const std::string& spec)
    : VideoCaptureSource(std::move(camera_name), frame_size, kind_of(spec), spec) {}

VideoCaptureSource::VideoCaptureSource(std::string camera_name, cv::Size frame_size, Kind kind,
                                       std::string spec)
    : name_(std::move(camera_name)),
      frame_size_(frame_size),
      spec_(std::move(spec)),
      kind_(kind),
      capture_(std::make_unique<cv::VideoCapture>()) {
  switch (kind_) {
    case Kind::kDevice:
      what_ = "device " + spec_;
      if (!all_digits(spec_) || spec_.size() >= 6) {
        open_problem_ = "cannot open " + what_ + ": a device is named by its index (0 .. 99999)";
        return;
      }
      break;
    case Kind::kPipeline:
      what_ = "GStreamer pipeline '" + spec_ + "'";
      break;
    case Kind::kStream:
      what_ = "stream '" + spec_ + "'";
      break;
    case Kind::kFile:
      what_ = "video file '" + spec_ + "'";
      break;
  }
  open();
}

VideoCaptureSource::~VideoCaptureSource() = default;

void VideoCaptureSource::open() {
  if (kind_ == Kind::kFile && !std::filesystem::is_regular_file(spec_)) {
    open_problem_ = "cannot open " + what_ + ": no such file";
    return;
  }
  try {
    // A device index is a V4L2 device on Linux: asking that backend alone keeps OpenCV from
    // probing every other camera library (slow, and some of them leak).
    const bool opened = kind_ == Kind::kDevice     ? capture_->open(std::stoi(spec_), kDeviceApi)
                        : kind_ == Kind::kPipeline ? capture_->open(spec_, cv::CAP_GSTREAMER)
                                                   : capture_->open(spec_);
    if (!opened) open_problem_ = "cannot open " + what_;
  } catch (const cv::Exception& error) {
    open_problem_ = "cannot open " + what_ + ": " + error.what();
  }
}

HealthReport VideoCaptureSource::grab() {
  if (!opened()) return camera_fault_report(name_, CameraFault::kUnavailable, open_problem_);
  if (!capture_->grab()) {
    return camera_fault_report(
        name_, CameraFault::kStopped,
        what_ + " delivered no frame after " + std::to_string(frames_grabbed_) + " frames");
  }
  ++frames_grabbed_;
  // Read now: the position belongs to the frame just grabbed.
  const double position_ms = capture_->get(cv::CAP_PROP_POS_MSEC);
  grabbed_exposure_s_.reset();
  if (kind_ == Kind::kFile || position_ms > 0.0) grabbed_exposure_s_ = position_ms / 1000.0;
  return {};
}

HealthReport VideoCaptureSource::retrieve(SourceFrame& frame) {
  frame = SourceFrame{};
  if (!capture_->retrieve(frame.image) || frame.image.empty()) {
    return camera_fault_report(
        name_, CameraFault::kCorruptFrame,
        what_ + " could not decode frame " + std::to_string(frames_grabbed_));
  }
  frame.exposure_s = grabbed_exposure_s_;
  if (kind_ == Kind::kFile) frame.origin = spec_ + ", frame " + std::to_string(frames_grabbed_);
  return {};
}

}  // namespace safecell
