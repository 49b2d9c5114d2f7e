#include "safecell/health/camera_health_monitor.hpp"

#include <gtest/gtest.h>

#include <opencv2/imgproc.hpp>

#include "safecell/cell/cell_model.hpp"
#include "safecell/cell/default_cell.hpp"
#include "safecell/sim/cell_simulation.hpp"
#include "safecell/sim/human_walker.hpp"

namespace safecell {
namespace {

const std::vector<double> kPose{0.4, 0.5, 0.6, 0.3, 0.8, 0.2};

// The default cell's first camera alone, with sensor noise sigma 2.
SimulatedCell first_camera() {
  CellModel model = load_cell_model(default_cell());
  model.cameras.erase(model.cameras.begin() + 1, model.cameras.end());
  return simulate_cell(model, SensorSettings{2.0, 0.0, 30.0, 5});
}

class CameraHealth : public ::testing::Test {
 protected:
  CameraHealth() : sim_(first_camera()) {
    reference_ = sim_.render(SimScene{kPose, {}}, 0, 0.0)[0];
    frame_ = sim_.render(SimScene{kPose, {}}, 1, 0.0)[0];
  }
  SimulatedCell sim_;
  cv::Mat reference_;
  cv::Mat frame_;
};

TEST_F(CameraHealth, ANoisyLiveCameraRaisesNoAlarmOverAThousandFrames) {
  CameraHealthMonitor monitor("cam0", reference_);
  const HumanWalker walker({{1.8, -1.8}, {0.8, -0.6}, {1.8, 1.0}, {-1.0, 1.6}});
  for (int frame = 0; frame < 1000; ++frame) {
    const double time_s = frame / 30.0;
    const SimScene scene{{0.8 * std::sin(0.5 * time_s), 0.5, 0.6, 0.3, 0.8, 0.2},
                         {walker.pose_at(std::fmod(time_s, walker.arrival_time_s()))}};
    const HealthReport report =
        monitor.check(sim_.render(scene, static_cast<std::uint64_t>(frame) + 10, time_s)[0]);
    ASSERT_TRUE(report.healthy()) << "frame " << frame << ": " << report.detail;
  }
}

TEST_F(CameraHealth, AFrozenPictureIsCaughtAfterThreeStillFrames) {
  CameraHealthMonitor monitor("cam0", reference_);
  for (int repeat = 0; repeat < 3; ++repeat) EXPECT_TRUE(monitor.check(frame_).healthy()) << repeat;
  const HealthReport report = monitor.check(frame_);
  EXPECT_EQ(report.fault, CameraFault::kFrozen);
  EXPECT_NE(report.detail.find("camera 'cam0': frozen image"), std::string::npos) << report.detail;
  // A live frame again: healthy.
  EXPECT_TRUE(monitor.check(sim_.render(SimScene{kPose, {}}, 2, 0.0)[0]).healthy());
}

TEST_F(CameraHealth, BlackSaturatedAndRelitPicturesAreCaught) {
  CameraHealthMonitor monitor("cam0", reference_);
  EXPECT_EQ(monitor.check(frame_ * 0.02).fault, CameraFault::kBlack);
  cv::Mat blinded = frame_.clone();
  blinded(cv::Rect(0, 0, blinded.cols, blinded.rows * 6 / 10)).setTo(255);
  EXPECT_EQ(monitor.check(blinded).fault, CameraFault::kSaturated);
  EXPECT_EQ(monitor.check(frame_ * 1.5).fault, CameraFault::kLightingChange);
  EXPECT_EQ(monitor.check(frame_ * 0.6).fault, CameraFault::kLightingChange);
  EXPECT_TRUE(monitor.check(frame_).healthy());
}

TEST_F(CameraHealth, AMovedCameraIsCaught) {
  CameraHealthMonitor monitor("cam0", reference_);
  for (const double shift_px : {4.0, 8.0, 20.0}) {
    const cv::Mat translation = (cv::Mat_<double>(2, 3) << 1, 0, shift_px, 0, 1, shift_px / 2);
    cv::Mat moved;
    cv::warpAffine(frame_, moved, translation, frame_.size(), cv::INTER_LINEAR, cv::BORDER_REFLECT);
    const HealthReport report = monitor.check(moved);
    EXPECT_EQ(report.fault, CameraFault::kMoved) << shift_px << " px: " << report.detail;
  }
  // Below the limit (3 px) the view stays in use: the shift is measured, not guessed.
  for (const double shift_px : {0.0, 1.0, 2.0}) {
    const cv::Mat translation = (cv::Mat_<double>(2, 3) << 1, 0, shift_px, 0, 1, 0);
    cv::Mat moved;
    cv::warpAffine(frame_, moved, translation, frame_.size(), cv::INTER_LINEAR, cv::BORDER_REFLECT);
    const HealthReport report = monitor.check(moved);
    EXPECT_TRUE(report.healthy()) << shift_px << " px: " << report.detail;
  }
}

TEST_F(CameraHealth, WrongFramesAreNamed) {
  CameraHealthMonitor monitor("cam0", reference_);
  EXPECT_EQ(monitor.check(cv::Mat()).fault, CameraFault::kWrongFormat);
  cv::Mat color;
  cv::cvtColor(frame_, color, cv::COLOR_GRAY2BGR);
  EXPECT_EQ(monitor.check(color).fault, CameraFault::kWrongFormat);
  const HealthReport small = monitor.check(cv::Mat(288, 352, CV_8UC1, cv::Scalar(100)));
  EXPECT_EQ(small.fault, CameraFault::kWrongFormat);
  EXPECT_NE(small.detail.find("got 352 x 288"), std::string::npos) << small.detail;
  EXPECT_THROW(CameraHealthMonitor("cam0", cv::Mat()), std::invalid_argument);
}

}  // namespace
}  // namespace safecell
