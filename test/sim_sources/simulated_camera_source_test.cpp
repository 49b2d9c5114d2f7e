#include "safecell/sim_sources/simulated_camera_source.hpp"

#include <gtest/gtest.h>

#include "safecell/acquisition/frame_set_acquirer.hpp"
#include "safecell/cell/cell_model.hpp"
#include "safecell/cell/default_cell.hpp"
#include "safecell/sim/cell_simulation.hpp"

namespace safecell {
namespace {

constexpr double kPeriodS = 0.04;

TEST(SimulatedCameraSource, AFrameSetRendersTheCellOnceAtTheFramesTime) {
  const CellModel model = load_cell_model(default_cell());
  std::vector<double> scene_times_s;
  auto rig = std::make_shared<SimulatedCameraRig>(
      simulate_cell(model, SensorSettings{}),
      [&scene_times_s](double time_s) {
        scene_times_s.push_back(time_s);
        return SimScene{{0.4, 0.5, 0.6, 0.3, 0.8, 0.2}, {}};
      },
      kPeriodS);
  FrameSetAcquirer acquirer(simulated_camera_sources(rig));
  ASSERT_EQ(acquirer.camera_count(), model.cameras.size());
  for (int set_index = 0; set_index < 3; ++set_index) {
    const FrameSet set = acquirer.acquire();
    EXPECT_EQ(rig->renders(), static_cast<std::uint64_t>(set_index + 1));
    for (std::size_t i = 0; i < set.frames.size(); ++i) {
      const CameraFrame& frame = set.frames[i];
      const CameraIntrinsics& intrinsics = model.cameras[i].intrinsics();
      ASSERT_TRUE(frame.known()) << frame.view.detail;
      EXPECT_EQ(frame.camera, model.cameras[i].name());
      EXPECT_EQ(frame.image.size(), cv::Size(intrinsics.width_px, intrinsics.height_px));
      EXPECT_EQ(frame.counter, static_cast<std::uint64_t>(set_index + 1));
      EXPECT_EQ(frame.stamp_source, StampSource::kBackend);
      EXPECT_DOUBLE_EQ(frame.exposure_s, set_index * kPeriodS);
    }
  }
  EXPECT_EQ(scene_times_s, (std::vector<double>{0.0, kPeriodS, 2 * kPeriodS}));
}

TEST(SimulatedCameraSource, AFailingSceneStopsTheCamerasByName) {
  CellModel model = load_cell_model(default_cell());
  model.cameras.erase(model.cameras.begin() + 1, model.cameras.end());
  auto rig = std::make_shared<SimulatedCameraRig>(
      simulate_cell(model, SensorSettings{}),
      [](double) -> SimScene { throw std::runtime_error("no scene"); }, kPeriodS);
  FrameSetAcquirer acquirer(simulated_camera_sources(rig));
  const CameraFrame frame = acquirer.acquire().frames.at(0);
  EXPECT_EQ(frame.view.fault, CameraFault::kStopped);
  EXPECT_NE(frame.view.detail.find("camera '" + model.cameras[0].name() +
                                   "': camera stopped delivering (simulated frame 0 failed: "
                                   "no scene)"),
            std::string::npos)
      << frame.view.detail;
  EXPECT_THROW(SimulatedCameraRig(
                   simulate_cell(model, SensorSettings{}), [](double) { return SimScene{}; }, 0.0),
               std::invalid_argument);
}

}  // namespace
}  // namespace safecell
