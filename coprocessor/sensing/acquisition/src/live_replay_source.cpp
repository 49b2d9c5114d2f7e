#include "safecell/acquisition/live_replay_source.hpp"

#include <chrono>
#include <stdexcept>
#include <thread>

namespace safecell {
namespace {

using Steady = std::chrono::steady_clock;

double steady_now_s() {
  return std::chrono::duration<double>(Steady::now().time_since_epoch()).count();
}

}  // namespace

double ReplayClock::due_s(double recorded_s) {
  if (!steady_minus_recorded_s_) steady_minus_recorded_s_ = steady_now_s() - recorded_s;
  return recorded_s + *steady_minus_recorded_s_;
}

double ReplayClock::pass_over_before_s(double late_limit_s) {
  if (!taken_) {
    pass_over_before_s_ = steady_now_s() - late_limit_s;
    taken_ = true;
  }
  return pass_over_before_s_;
}

LiveReplaySource::LiveReplaySource(std::unique_ptr<CameraSource> recording,
                                   std::shared_ptr<ReplayClock> clock)
    : recording_(std::move(recording)), clock_(std::move(clock)) {
  if (!recording_ || !clock_) {
    throw std::invalid_argument("live replay: a recording and a replay clock are both needed");
  }
}

HealthReport LiveReplaySource::retrieve(SourceFrame& frame) {
  HealthReport report = recording_->retrieve(frame);
  if (!report.healthy()) return report;
  if (!frame.exposure_s) {
    frame.exposure_s = steady_now_s();
    return report;
  }
  double due_s = clock_->due_s(*frame.exposure_s);
  // Behind (the service stalled, waiting for a controller): a live camera would show a newer
  // frame by now, so the frames long due are passed over, as it would have overwritten them.
  // Handing them out would send maps of data older than the controller accepts, for ever after.
  const double pass_over_before_s = clock_->pass_over_before_s(kLateLimit_s);
  while (due_s < pass_over_before_s) {
    // The recording's own grab, not this source's: passing over stays within the frame set.
    if (!recording_->grab().healthy()) break;  // the recording's end: this frame, late
    SourceFrame next;
    if (!recording_->retrieve(next).healthy() || !next.exposure_s) {
      // A frame that could not be read (or has no time) is taken from the recording all the
      // same: counted as passed over, so that the recording's sets stay accounted for.
      ++frame.passed_over;
      ++passed_over_;
      break;
    }
    next.passed_over = frame.passed_over + 1;
    frame = std::move(next);
    due_s = clock_->due_s(*frame.exposure_s);
    ++passed_over_;
  }
  std::this_thread::sleep_until(Steady::time_point(
      std::chrono::duration_cast<Steady::duration>(std::chrono::duration<double>(due_s))));
  frame.exposure_s = due_s;
  return report;
}

}  // namespace safecell
