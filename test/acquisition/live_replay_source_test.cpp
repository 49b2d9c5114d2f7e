// A recording played as live cameras: after a stall the frames long due are passed over, and the
// cameras of one recording pass over the same ones even when one of them is slow to decode.

#include "safecell/acquisition/live_replay_source.hpp"

#include <gtest/gtest.h>

#include <chrono>
#include <thread>

#include "safecell/acquisition/frame_set_acquirer.hpp"

namespace safecell {
namespace {

constexpr double kPeriod_s = 1.0 / 30.0;

// A recorded camera: frame n was exposed at n / 30 s and its pixels say n; each retrieve takes
// decode_ms (a slow decoder).
class RecordedCamera final : public CameraSource {
 public:
  RecordedCamera(std::string name, int decode_ms) : name_(std::move(name)), decode_ms_(decode_ms) {}
  [[nodiscard]] const std::string& name() const override { return name_; }
  [[nodiscard]] cv::Size frame_size() const override { return {16, 12}; }
  HealthReport grab() override {
    ++latched_;
    return {};
  }
  HealthReport retrieve(SourceFrame& frame) override {
    std::this_thread::sleep_for(std::chrono::milliseconds(decode_ms_));
    frame = SourceFrame{cv::Mat(frame_size(), CV_8UC1, cv::Scalar(latched_ % 256)),
                        latched_ * kPeriod_s, "recording"};
    return {};
  }

 private:
  std::string name_;
  int decode_ms_;
  int latched_ = -1;
};

int frame_number(const CameraFrame& frame) { return frame.image.at<std::uint8_t>(0, 0); }

TEST(LiveReplaySource, AfterAStallTheCamerasPassOverTheSameFrames) {
  const auto clock = std::make_shared<ReplayClock>();
  std::vector<std::unique_ptr<CameraSource>> sources;
  // Camera 0 decodes slowly: passing over a dozen frames takes it longer than a frame period.
  sources.push_back(
      std::make_unique<LiveReplaySource>(std::make_unique<RecordedCamera>("cam0", 15), clock));
  sources.push_back(
      std::make_unique<LiveReplaySource>(std::make_unique<RecordedCamera>("cam1", 0), clock));
  const auto* first = dynamic_cast<const LiveReplaySource*>(sources[0].get());
  const auto* second = dynamic_cast<const LiveReplaySource*>(sources[1].get());
  FrameSetAcquirer cameras(std::move(sources));

  const FrameSet start = cameras.acquire();
  ASSERT_EQ(start.known_count(), 2U);
  EXPECT_EQ(frame_number(start.frames[0]), 0);
  EXPECT_EQ(frame_number(start.frames[1]), 0);

  std::this_thread::sleep_for(std::chrono::milliseconds(700));  // the service stalled
  const FrameSet after = cameras.acquire();
  ASSERT_EQ(after.known_count(), 2U);
  // Frames due more than kLateLimit_s ago were passed over, the same ones by both cameras.
  EXPECT_GE(first->passed_over(), 10U);
  EXPECT_EQ(first->passed_over(), second->passed_over());
  // The set says so, and the acquirer counts it: the sets exposed are all accounted for.
  EXPECT_EQ(after.frames[0].passed_over, first->passed_over());
  EXPECT_EQ(after.frames[1].passed_over, second->passed_over());
  EXPECT_EQ(start.frames[0].passed_over, 0U);
  EXPECT_EQ(cameras.sets_acquired(), 2U);
  EXPECT_EQ(cameras.sets_passed_over(), first->passed_over());
  EXPECT_EQ(frame_number(after.frames[0]), frame_number(after.frames[1]));
  EXPECT_DOUBLE_EQ(after.frames[0].exposure_s, after.frames[1].exposure_s);
}

}  // namespace
}  // namespace safecell
