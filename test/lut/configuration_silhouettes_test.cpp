// The robot's silhouette at one configuration (robot removal): it holds every pixel the rendered
// robot covers there, it is much smaller than LUT-1 of the robot's cell, and its widening covers
// the motion within the time-sync error.

#include "safecell/silhouettes/configuration_silhouettes.hpp"

#include <gtest/gtest.h>

#include "model_fixture.hpp"
#include "safecell/silhouettes/model_silhouettes.hpp"
#include "safecell/sim/cell_simulation.hpp"
#include "safecell/test/property.hpp"

namespace safecell {
namespace {

TEST(ConfigurationSilhouettes, HoldTheRenderedRobotAndAreTighterThanLutOne) {
  const CellModel cell = test::coarse_default_cell();
  const CspaceGrid grid = make_grid(cell.config);
  const ConfigurationSilhouettes at_configuration(cell, 0.06, 0.0);
  const ModelSilhouettes per_cell(cell, grid, ModelLutOptions{});
  SimulatedCell sim = simulate_cell(cell, SensorSettings{});
  const FeatureGrid& features = cell.feature_grid;
  test::PropertyRun run(15);
  std::uniform_int_distribution<CellIndex> any_cell(0, grid.cell_count() - 1);
  std::size_t tight = 0, whole_cell = 0;
  for (int i = 0; i < run.iterations(); ++i) {
    const CellIndex cell_index = any_cell(run.rng());
    const auto q = test::configuration_in(grid, cell_index, run.rng());
    std::vector<FeatureMask> masks(sim.camera_count(), FeatureMask(features));
    at_configuration.add_silhouettes(q, masks);
    std::vector<FeatureMask> cell_masks(sim.camera_count(), FeatureMask(features));
    per_cell.add_silhouettes(cell_index, cell_masks);
    for (std::size_t camera = 0; camera < sim.camera_count(); ++camera) {
      const cv::Mat covered = sim.robot_coverage(camera, q);
      for (int y = 0; y < covered.rows; ++y) {
        for (int x = 0; x < covered.cols; ++x) {
          if (covered.at<std::uint8_t>(y, x) == 0) continue;
          ASSERT_TRUE(
              masks[camera].test(x / features.cell_width_px(), y / features.cell_height_px()))
              << "camera " << camera << " pixel " << x << "," << y << " q[0] " << q[0];
        }
      }
      tight += masks[camera].count();
      whole_cell += cell_masks[camera].count();
    }
  }
  EXPECT_LT(2 * tight, whole_cell) << "the silhouette at the configuration should be far tighter";
}

TEST(ConfigurationSilhouettes, TheWideningAddsTheMotionWithinTheSyncError) {
  const CellModel cell = test::coarse_default_cell();
  const CspaceGrid grid = make_grid(cell.config);
  EXPECT_DOUBLE_EQ(removal_widening_m(*cell.robot, grid, 0.02, 0.0).value(), 0.02);
  double motion_m = 0.0;
  for (std::uint32_t j = 0; j < grid.joint_count(); ++j) {
    motion_m += grid.joint(j).l_m * cell.robot->joints[j].max_speed * 0.004;
  }
  EXPECT_GT(motion_m, 0.0);
  EXPECT_NEAR(removal_widening_m(*cell.robot, grid, 0.02, 0.004).value(), 0.02 + motion_m, 1e-12);
  RobotModel unlimited = *cell.robot;
  unlimited.joints[1].max_speed = 0.0;  // a URDF without a velocity limit: motion unbounded
  EXPECT_FALSE(removal_widening_m(unlimited, grid, 0.02, 0.004).has_value());
  // A wider silhouette holds the narrower one.
  const ConfigurationSilhouettes narrow(cell, 0.06, 0.0), wide(cell, 0.06, 0.1);
  const std::vector<double> q{0.3, -0.4, 1.1, 0.2, 0.6, 0.0};
  std::vector<FeatureMask> a(cell.cameras.size(), FeatureMask(cell.feature_grid));
  std::vector<FeatureMask> b = a;
  narrow.add_silhouettes(q, a);
  wide.add_silhouettes(q, b);
  for (std::size_t c = 0; c < a.size(); ++c) {
    FeatureMask outside = a[c];
    outside.subtract(b[c]);
    EXPECT_FALSE(outside.any()) << "camera " << c;
    EXPECT_GT(b[c].count(), a[c].count()) << "camera " << c;
  }
  const std::vector<double> two_joints{0.1, 0.2};
  EXPECT_THROW(narrow.add_silhouettes(two_joints, a), std::invalid_argument);
  EXPECT_THROW(ConfigurationSilhouettes(cell, 0.06, -0.1), std::invalid_argument);
}

}  // namespace
}  // namespace safecell
