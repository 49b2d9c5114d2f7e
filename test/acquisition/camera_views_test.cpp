#include "safecell/acquisition/camera_views.hpp"

#include <gtest/gtest.h>

#include <opencv2/imgproc.hpp>

#include "safecell/acquisition/frame_set_acquirer.hpp"
#include "scripted_source.hpp"

namespace safecell {
namespace {

using test::ScriptedSource;

cv::Size frame_size() { return {176, 144}; }

// A textured empty cell: smooth random blobs around gray 128.
cv::Mat reference_image() {
  cv::Mat coarse(frame_size().height / 8, frame_size().width / 8, CV_8UC1);
  cv::RNG rng(7);
  rng.fill(coarse, cv::RNG::UNIFORM, 60, 196);
  cv::Mat image;
  cv::resize(coarse, image, frame_size(), 0, 0, cv::INTER_CUBIC);
  return image;
}

// The reference with fresh sensor noise (sigma 2) for every frame, as a live camera sees it.
cv::Mat live_frame(const cv::Mat& reference, int frame) {
  cv::Mat noise(reference.size(), CV_16SC1);
  cv::RNG rng(static_cast<std::uint64_t>(1000 + frame));
  rng.fill(noise, cv::RNG::NORMAL, 0, 2);
  cv::Mat noisy;
  cv::add(reference, noise, noisy, cv::noArray(), CV_8U);
  return noisy;
}

class CameraViewsTest : public ::testing::Test {
 protected:
  // Three cameras over the same scene; "mid" shows black frames in grabs 2 and 3 and is
  // unavailable in grab 5.
  CameraViewsTest() {
    std::vector<std::unique_ptr<CameraSource>> sources;
    std::vector<CameraHealthMonitor> monitors;
    for (const std::string name : {"left", "mid", "right"}) {
      const bool faulty = name == "mid";
      sources.push_back(std::make_unique<ScriptedSource>(
          name, frame_size(),
          [this, faulty](int grab) {
            const cv::Mat frame = live_frame(reference_, grab);
            return faulty && (grab == 2 || grab == 3) ? cv::Mat(frame * 0.02) : frame;
          },
          nullptr,
          [faulty](int grab) {
            return faulty && grab == 5 ? CameraFault::kUnavailable : CameraFault::kNone;
          }));
      monitors.emplace_back(name, reference_);
    }
    acquirer_ = std::make_unique<FrameSetAcquirer>(std::move(sources));
    views_ = std::make_unique<CameraViews>(
        std::move(monitors), [this](std::string_view line) { log_.emplace_back(line); });
  }

  FrameSet next() {
    FrameSet set = acquirer_->acquire();
    views_->check(set);
    return set;
  }

  cv::Mat reference_ = reference_image();
  std::unique_ptr<FrameSetAcquirer> acquirer_;
  std::unique_ptr<CameraViews> views_;
  std::vector<std::string> log_;
};

TEST_F(CameraViewsTest, ABlackCameraIsUnknownWithItsCauseAndLoggedOnceUntilItRecovers) {
  // Grabs of "mid": 0, 1 live; 2, 3 black; 4 live.
  for (int set_index = 0; set_index < 2; ++set_index) {
    const FrameSet set = next();
    EXPECT_EQ(set.known_count(), 3U) << set.frames[1].view.detail;
  }
  EXPECT_TRUE(log_.empty());
  for (int set_index = 2; set_index < 4; ++set_index) {
    const FrameSet set = next();
    EXPECT_EQ(set.known_count(), 2U);
    EXPECT_TRUE(set.frames[0].known());
    EXPECT_TRUE(set.frames[2].known());
    EXPECT_EQ(set.frames[1].view.fault, CameraFault::kBlack);
    EXPECT_NE(set.frames[1].view.detail.find("camera 'mid': black image"), std::string::npos)
        << set.frames[1].view.detail;
  }
  ASSERT_EQ(log_.size(), 1U);
  EXPECT_EQ(log_[0].rfind("view unknown: camera 'mid': black image (mean ", 0), 0U) << log_[0];
  EXPECT_EQ(next().known_count(), 3U);
  ASSERT_EQ(log_.size(), 2U);
  EXPECT_EQ(log_[1], "view known again: camera 'mid' (was: black image)");
}

TEST_F(CameraViewsTest, AcquisitionFaultsPassThroughAndAreLogged) {
  for (int set_index = 0; set_index < 5; ++set_index) static_cast<void>(next());
  log_.clear();
  const FrameSet set = next();
  EXPECT_EQ(set.frames[1].view.fault, CameraFault::kUnavailable);
  EXPECT_EQ(set.known_count(), 2U);
  ASSERT_EQ(log_.size(), 1U);
  EXPECT_EQ(log_[0], "view unknown: camera 'mid': camera unavailable (scripted)");
  EXPECT_EQ(next().known_count(), 3U);
  ASSERT_EQ(log_.size(), 2U);
  EXPECT_EQ(log_[1], "view known again: camera 'mid' (was: camera unavailable)");
}

TEST_F(CameraViewsTest, RefusesFrameSetsOfOtherCameras) {
  FrameSet set = acquirer_->acquire();
  set.frames[2].camera = "elsewhere";
  EXPECT_THROW(views_->check(set), std::invalid_argument);
  set.frames.pop_back();
  EXPECT_THROW(views_->check(set), std::invalid_argument);
}

}  // namespace
}  // namespace safecell
