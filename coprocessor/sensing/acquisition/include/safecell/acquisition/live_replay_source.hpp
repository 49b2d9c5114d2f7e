#pragma once
// A recorded camera (an image folder, a video file) played as a live one, for the service running
// on a recording: a frame is handed out once as much time has passed since the recording's first
// frame as its recorded exposure lies after that frame's, and it is stamped with that moment on
// the steady clock, the clock the link matches the robot's joint stream against. The cameras of
// one recording share a ReplayClock, so their frames keep their recorded offsets to each other.
// Thread context: the acquisition thread; not synchronised.

#include <cstddef>
#include <memory>
#include <optional>
#include <string>

#include "safecell/acquisition/camera_source.hpp"

namespace safecell {

class ReplayClock {
 public:
  // The steady-clock time (seconds since its epoch) at which a frame recorded at `recorded_s`
  // (the recording's clock) is due. The first call ties the recording's clock to now.
  double due_s(double recorded_s);
  // A frame set begins (a camera's grab(): a set grabs every camera before it retrieves any).
  void new_set() { taken_ = false; }
  // Frames due before this steady-clock time are passed over (now - late_limit_s). Taken once
  // per frame set, by its first retrieve, so that every camera passes over the same frames and
  // they stay in step however long the first one took to pass over its own.
  double pass_over_before_s(double late_limit_s);

 private:
  std::optional<double> steady_minus_recorded_s_;
  double pass_over_before_s_ = 0.0;
  bool taken_ = false;
};

class LiveReplaySource final : public CameraSource {
 public:
  // Throws std::invalid_argument when either argument is null.
  LiveReplaySource(std::unique_ptr<CameraSource> recording, std::shared_ptr<ReplayClock> clock);

  [[nodiscard]] const std::string& name() const override { return recording_->name(); }
  [[nodiscard]] cv::Size frame_size() const override { return recording_->frame_size(); }

  HealthReport grab() override {
    clock_->new_set();
    return recording_->grab();
  }
  // The recording's frame, after waiting until it is due; its exposure is then the due time on
  // the steady clock. A frame without a recorded time is handed out at once, stamped now. Frames
  // due more than kLateLimit_s ago are passed over for the first one that is not (a live camera
  // keeps only its newest frame); the cameras of one recording pass over the same ones, as their
  // due times are the same.
  HealthReport retrieve(SourceFrame& frame) override;

  static constexpr double kLateLimit_s = 0.1;
  // Frames passed over so far.
  [[nodiscard]] std::size_t passed_over() const { return passed_over_; }

 private:
  std::unique_ptr<CameraSource> recording_;
  std::shared_ptr<ReplayClock> clock_;
  std::size_t passed_over_ = 0;
};

}  // namespace safecell
