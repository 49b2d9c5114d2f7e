#pragma once
// A recorded camera (an image folder, a video file) played as a live one, for the service running
// on a recording: a frame is handed out once as much time has passed since the recording's first
// frame as its recorded exposure lies after that frame's, and it is stamped with that moment on
// the steady clock, the clock the link matches the robot's joint stream against. The cameras of
// one recording share a ReplayClock, so their frames keep their recorded offsets to each other.
// Thread context: the acquisition thread; not synchronised.

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

 private:
  std::optional<double> steady_minus_recorded_s_;
};

class LiveReplaySource final : public CameraSource {
 public:
  // Throws std::invalid_argument when either argument is null.
  LiveReplaySource(std::unique_ptr<CameraSource> recording, std::shared_ptr<ReplayClock> clock);

  [[nodiscard]] const std::string& name() const override { return recording_->name(); }
  [[nodiscard]] cv::Size frame_size() const override { return recording_->frame_size(); }

  HealthReport grab() override { return recording_->grab(); }
  // The recording's frame, after waiting until it is due; its exposure is then the due time on
  // the steady clock. A frame without a recorded time is handed out at once, stamped now.
  HealthReport retrieve(SourceFrame& frame) override;

 private:
  std::unique_ptr<CameraSource> recording_;
  std::shared_ptr<ReplayClock> clock_;
};

}  // namespace safecell
