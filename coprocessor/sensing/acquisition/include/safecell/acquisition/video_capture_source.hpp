#pragma once
// A camera read through OpenCV's VideoCapture: a capture device, a video file, a GStreamer
// pipeline or a network stream (RTSP, HTTP). The spec string decides which:
//   "0", "2"                                  device index (V4L2 on Linux; up to 5 digits)
//   "v4l2src device=/dev/video0 ! appsink"   GStreamer pipeline (it contains '!')
//   "rtsp://10.0.0.5/stream1"                network stream (it contains "://")
//   anything else                            video file
// A source that cannot be opened stays closed (opening again may take seconds, which would stall
// every frame set): each grab() reports kUnavailable with the reason; make a new source to retry.
// Exposure times: a video file's media time; a device's, pipeline's or stream's own time stamp
// when the backend gives one (non-zero), else none (the acquirer then uses the grab time).

#include <cstdint>
#include <memory>
#include <optional>
#include <string>

#include "safecell/acquisition/camera_source.hpp"

namespace cv {
class VideoCapture;
}  // namespace cv

namespace safecell {

class VideoCaptureSource final : public CameraSource {
 public:
  enum class Kind { kDevice, kPipeline, kStream, kFile };

  // What `spec` reads as by the rules above.
  [[nodiscard]] static Kind kind_of(const std::string& spec);

  // Opens the capture now, `spec` read as kind_of(spec); see opened().
  VideoCaptureSource(std::string camera_name, cv::Size frame_size, const std::string& spec);
  // Opens `spec` as `kind`, whatever it looks like (a cell file says which kind it means: a
  // video file named "0" or with a '!' in its path stays a file). A kDevice spec must be digits.
  VideoCaptureSource(std::string camera_name, cv::Size frame_size, Kind kind, std::string spec);
  ~VideoCaptureSource() override;
  VideoCaptureSource(const VideoCaptureSource&) = delete;
  VideoCaptureSource& operator=(const VideoCaptureSource&) = delete;
  VideoCaptureSource(VideoCaptureSource&&) = delete;
  VideoCaptureSource& operator=(VideoCaptureSource&&) = delete;

  [[nodiscard]] const std::string& name() const override { return name_; }
  [[nodiscard]] cv::Size frame_size() const override { return frame_size_; }
  // Whether the capture opened; when not, open_problem() says why.
  [[nodiscard]] bool opened() const { return open_problem_.empty(); }
  [[nodiscard]] const std::string& open_problem() const { return open_problem_; }

  HealthReport grab() override;
  HealthReport retrieve(SourceFrame& frame) override;

 private:
  void open();

  std::string name_;
  cv::Size frame_size_;
  std::string spec_;
  Kind kind_ = Kind::kFile;
  std::string what_;  // "device 0", "video file 'x.avi'", ... for messages
  std::string open_problem_;
  std::unique_ptr<cv::VideoCapture> capture_;
  std::optional<double> grabbed_exposure_s_;
  std::uint64_t frames_grabbed_ = 0;
};

}  // namespace safecell
