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
  const double due_s = clock_->due_s(*frame.exposure_s);
  std::this_thread::sleep_until(Steady::time_point(
      std::chrono::duration_cast<Steady::duration>(std::chrono::duration<double>(due_s))));
  frame.exposure_s = due_s;
  return report;
}

}  // namespace safecell
