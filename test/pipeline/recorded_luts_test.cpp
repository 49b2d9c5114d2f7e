// Recorded mode on the coarse default cell, with the simulated cell standing in for the real
// robot and cameras: keys, conservative silhouettes, the stored set, and the check against the
// model that flags a camera whose calibration is off.

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <random>

#include "model_fixture.hpp"
#include "safecell/errors/input_error.hpp"
#include "safecell/fusion/forbidden_map_fusion.hpp"
#include "safecell/lut_build/recorded_luts.hpp"
#include "safecell/lut_files/lut_file.hpp"
#include "safecell/silhouettes/silhouette_agreement.hpp"
#include "safecell/silhouettes/table_silhouettes.hpp"
#include "safecell/sim/cell_simulation.hpp"
#include "safecell/sim_sources/simulated_reference.hpp"
#include "safecell/sim_sources/simulated_robot_viewer.hpp"
#include "safecell/test/property.hpp"
#include "silhouette_check.hpp"

namespace safecell {
namespace {

RecordingOptions quick_options(int stride) {
  RecordingOptions options;
  options.key_stride = stride;
  options.wrist_samples = 1;
  return options;
}

// The coarse default cell three times as wide, the cameras three times as far from the robot and
// zoomed in to match: far enough for the recording's bound (RecordedSilhouettes) to stay small.
CellModel far_cameras_cell() {
  CellConfig config = default_cell();
  config.m_max_m = 0.4;  // as test::coarse_default_cell()
  config.joints.at(3).discretised = false;
  config.envelope_max_move_m.reset();
  for (double& side : config.size_m) side *= 3.0;
  for (auto& camera : config.cameras) {
    LookAtConfig& look = camera.look_at.value();
    for (std::size_t i = 0; i < 3; ++i) {
      look.position_m[i] = look.target_m[i] + 3.0 * (look.position_m[i] - look.target_m[i]);
    }
    look.horizontal_fov_deg /= 2.5;
  }
  return load_cell_model(config);
}

// Records the robot as `seen_by` shows it (the recording's cell, or one whose cameras are not
// where the recording's cell file says).
void record(RecordedSilhouettes& recording, const CellModel& seen_by) {
  SimulatedCell sim = simulate_cell(seen_by, SensorSettings{});
  const std::vector<cv::Mat> reference = simulated_reference(sim, seen_by, 9, 1).frames;
  SimulatedRobotViewer viewer(sim, seen_by, reference);
  recording.record([&viewer](const std::vector<double>& q) { return viewer(q); });
}

class RecordedTables : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    cell_ = new CellModel(far_cameras_cell());
    grid_ = new CspaceGrid(make_grid(cell_->config));
    recording_ = new RecordedSilhouettes(*cell_, *grid_, quick_options(3));
    record(*recording_, *cell_);
  }
  static void TearDownTestSuite() {
    delete recording_;
    delete grid_;
    delete cell_;
  }
  static CellModel* cell_;
  static CspaceGrid* grid_;
  static RecordedSilhouettes* recording_;
};

CellModel* RecordedTables::cell_ = nullptr;
CspaceGrid* RecordedTables::grid_ = nullptr;
RecordedSilhouettes* RecordedTables::recording_ = nullptr;

TEST_F(RecordedTables, KeysSpanTheGridAndCoarserKeysDilateMore) {
  const RecordedSilhouettes brute(*cell_, *grid_, quick_options(1));
  std::size_t cells_of_discretised = 1;
  for (std::uint32_t j = 0; j < grid_->joint_count(); ++j) {
    if (grid_->joint(j).discretised) cells_of_discretised *= grid_->cells_along(j);
  }
  EXPECT_EQ(brute.key_count(), cells_of_discretised);  // the paper's brute force: every cell
  EXPECT_LT(recording_->key_count(), brute.key_count() / 8);
  EXPECT_GT(recording_->motion_bound_m(), brute.motion_bound_m());
  for (std::size_t camera = 0; camera < cell_->cameras.size(); ++camera) {
    EXPECT_GE(brute.dilation_columns(camera), 1);
    EXPECT_GE(recording_->dilation_columns(camera), brute.dilation_columns(camera));
    EXPECT_GE(recording_->dilation_rows(camera), brute.dilation_rows(camera));
  }
  // The last cell of every discretised joint is a key, and keys sit at cell centres.
  const std::vector<double> last = recording_->configuration(recording_->key_count() - 1, 0);
  for (std::uint32_t j = 0; j < grid_->joint_count(); ++j) {
    const JointSpec& spec = grid_->joint(j);
    const double expected = spec.discretised ? spec.hi_rad - grid_->cell_width_rad(j) / 2.0
                                             : (spec.lo_rad + spec.hi_rad) / 2.0;
    EXPECT_NEAR(last[j], expected, 1e-9) << "joint " << j + 1;
  }
  RecordingOptions wrists;
  wrists.wrist_samples = 3;
  EXPECT_EQ(RecordedSilhouettes(*cell_, *grid_, wrists).wrist_combinations(), 27U);  // joints 4-6
}

TEST_F(RecordedTables, AbsurdOptionsAreRefused) {
  RecordingOptions options;
  options.key_stride = 0;
  EXPECT_THROW(RecordedSilhouettes(*cell_, *grid_, options), std::invalid_argument);
  options = RecordingOptions{};
  options.wrist_samples = 0;
  EXPECT_THROW(RecordedSilhouettes(*cell_, *grid_, options), std::invalid_argument);
  options = RecordingOptions{};
  options.padding_m = -0.1;
  EXPECT_THROW(RecordedSilhouettes(*cell_, *grid_, options), std::invalid_argument);
  RecordedSilhouettes recording(*cell_, *grid_, quick_options(3));
  EXPECT_THROW(
      recording.record([](const std::vector<double>&) { return std::vector<FeatureMask>(1); }),
      std::runtime_error);
  EXPECT_FALSE(recording.recorded());
}

TEST_F(RecordedTables, CamerasTooCloseForTheBoundSeeEverythingAndAreRefusedForTables) {
  EXPECT_TRUE(recording_->unbounded_cameras().empty());
  const CellModel near = test::coarse_default_cell();  // cameras about 1.2 m from the reach
  const CspaceGrid grid = make_grid(near.config);
  RecordedSilhouettes recording(near, grid, quick_options(3));
  ASSERT_EQ(recording.unbounded_cameras().size(), near.cameras.size());
  recording.record([&near](const std::vector<double>&) {
    return std::vector<FeatureMask>(near.cameras.size(), FeatureMask(near.feature_grid));
  });
  FeatureMask silhouette(near.feature_grid);
  recording.add_silhouette(0, 0, silhouette);
  EXPECT_EQ(silhouette.count(), near.feature_grid.cell_count());
  try {
    (void)build_recorded_luts(near, grid, recording);
    FAIL() << "tables built with unbounded cameras";
  } catch (const InputError& error) {
    EXPECT_NE(std::string(error.what()).find(near.cameras[0].name()), std::string::npos)
        << error.what();
  }
}

TEST_F(RecordedTables, SilhouettesHoldTheRenderedRobotAnywhereInTheCell) {
  test::expect_silhouettes_hold_rendered_robot(*cell_, *grid_, *recording_, 40);
}

TEST_F(RecordedTables, TheSetKeepsLut1AndSurvivesItsFile) {
  const LutSet set = build_recorded_luts(*cell_, *grid_, *recording_);
  EXPECT_EQ(set.source, LutSource::kRecorded);
  EXPECT_EQ(set.fingerprint, recorded_lut_fingerprint(*cell_, *grid_, recording_->options()));
  EXPECT_NE(set.fingerprint, recorded_lut_fingerprint(*cell_, *grid_, quick_options(2)));
  ASSERT_EQ(set.cameras.size(), cell_->cameras.size());
  FeatureMask expected(cell_->feature_grid);
  recording_->add_silhouette(17, 1, expected);
  EXPECT_EQ(set.cameras[1].cell_to_pixels.mask_of(17), expected);

  const auto path = std::filesystem::temp_directory_path() / "safecell_recorded_test.sclut";
  write_lut_file(path, set);
  const LutSet loaded = load_lut_file(path, *grid_, set.fingerprint);
  std::filesystem::remove(path);
  EXPECT_EQ(loaded.source, LutSource::kRecorded);
  EXPECT_EQ(loaded.cameras[1].cell_to_pixels.mask_of(17), expected);

  // Fusion runs on it with LUT-1 read from the table: the robot alone forbids nothing.
  std::vector<CellToPixelsTable> tables;
  for (const auto& camera : loaded.cameras) tables.push_back(camera.cell_to_pixels);
  const TableSilhouettes silhouettes(std::move(tables));
  ForbiddenMapFusion fusion(loaded, silhouettes, FusionSettings{});
  std::vector<CameraObservation> robot_alone;
  const CellIndex robot_cell = 17;
  for (std::size_t camera = 0; camera < loaded.cameras.size(); ++camera) {
    FeatureMask seen(cell_->feature_grid);
    recording_->add_silhouette(robot_cell, camera, seen);
    robot_alone.push_back(CameraObservation{true, seen});
  }
  EXPECT_EQ(fusion.fuse(robot_alone, robot_cell), loaded.static_cells);
}

TEST_F(RecordedTables, AgreeWithTheModelAndFlagAMiscalibratedCamera) {
  const ModelSilhouettes model(*cell_, *grid_, ModelLutOptions{});
  const auto calibrated = compare_with_model(*cell_, *grid_, *recording_, model);
  ASSERT_EQ(calibrated.size(), cell_->cameras.size());
  for (const auto& camera : calibrated) {
    EXPECT_FALSE(camera.flagged) << camera.camera << " coverage " << camera.coverage();
    EXPECT_GT(camera.keys, 0U) << camera.camera;
    EXPECT_GT(camera.fill(), 0.0) << camera.camera;
  }

  // The real camera 2 is turned 3 degrees about its optical axis and sideways from where the
  // cell file says it is: what it records no longer falls inside the model's silhouettes.
  CellModel real = *cell_;
  const PinholeCamera& nominal = cell_->cameras[1];
  const Eigen::Isometry3d turn(Eigen::AngleAxisd(3.0 * std::numbers::pi / 180.0,
                                                 Eigen::Vector3d(0.3, 1.0, 0.2).normalized()));
  real.cameras[1] =
      PinholeCamera(nominal.name(), nominal.intrinsics(), turn * nominal.cell_to_camera());
  RecordedSilhouettes off(*cell_, *grid_, quick_options(4));
  record(off, real);
  const auto agreement = compare_with_model(*cell_, *grid_, off, model);
  for (std::size_t camera = 0; camera < agreement.size(); ++camera) {
    EXPECT_EQ(agreement[camera].flagged, camera == 1)
        << agreement[camera].camera << " coverage " << agreement[camera].coverage();
  }
  EXPECT_LT(agreement[1].coverage(), calibrated[1].coverage());
}

}  // namespace
}  // namespace safecell
