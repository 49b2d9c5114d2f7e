#include "safecell/pipeline/sensing_pipeline.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <stdexcept>
#include <string>

#include "model_fixture.hpp"
#include "safecell/lut_build/model_luts.hpp"
#include "safecell/sim/cell_simulation.hpp"
#include "safecell/sim_sources/simulated_reference.hpp"
#include "safecell/test/property.hpp"

namespace safecell {
namespace {

class SensingPipelineTest : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    cell_ = new CellModel(test::coarse_default_cell());
    grid_ = new CspaceGrid(make_grid(cell_->config));
    luts_ = new LutSet(build_model_luts(*cell_, *grid_));
    silhouettes_ = new ModelSilhouettes(*cell_, *grid_, ModelLutOptions{});
    sim_ = new SimulatedCell(simulate_cell(*cell_, SensorSettings{}));
    reference_ = new std::vector<cv::Mat>(simulated_reference(*sim_, *cell_, 9, 3).frames);
  }
  static void TearDownTestSuite() {
    delete reference_;
    delete sim_;
    delete silhouettes_;
    delete luts_;
    delete grid_;
    delete cell_;
  }
  static SensingPipeline pipeline() {
    return SensingPipeline(*cell_, *grid_, *luts_, *silhouettes_, *reference_, {},
                           FusionSettings{});
  }

  static CellModel* cell_;
  static CspaceGrid* grid_;
  static LutSet* luts_;
  static ModelSilhouettes* silhouettes_;
  static SimulatedCell* sim_;
  static std::vector<cv::Mat>* reference_;
};

CellModel* SensingPipelineTest::cell_ = nullptr;
CspaceGrid* SensingPipelineTest::grid_ = nullptr;
LutSet* SensingPipelineTest::luts_ = nullptr;
ModelSilhouettes* SensingPipelineTest::silhouettes_ = nullptr;
SimulatedCell* SensingPipelineTest::sim_ = nullptr;
std::vector<cv::Mat>* SensingPipelineTest::reference_ = nullptr;

TEST_F(SensingPipelineTest, TheRobotAloneIsNoObstacle) {
  test::PropertyRun run(10);
  SensingPipeline sensing = pipeline();
  std::uniform_int_distribution<CellIndex> any_cell(0, grid_->cell_count() - 1);
  for (int i = 0; i < run.iterations(); ++i) {
    const auto q = test::configuration_in(*grid_, any_cell(run.rng()), run.rng());
    const CellSet& forbidden = sensing.process(
        sim_->render(SimScene{q, {}}, 100U + static_cast<std::uint64_t>(i), 0.0), q);
    for (std::size_t c = 0; c < cell_->cameras.size(); ++c) {
      EXPECT_EQ(sensing.fusion().counts().obstacle_pixels[c], 0U)
          << "camera " << c << " sample " << i;
    }
    EXPECT_EQ(forbidden, luts_->static_cells);
  }
}

TEST_F(SensingPipelineTest, APersonIsSeenAndForbidsCells) {
  SensingPipeline sensing = pipeline();
  // The arm turned away from the person, who stands in the far corner.
  const std::vector<double> q{0.78, 0.0, 1.0, 0.0, 0.5, 0.0};
  HumanPose person;
  person.position_m = {-1.6, -1.6};
  const CellSet& forbidden = sensing.process(sim_->render(SimScene{q, {person}}, 7, 0.0), q);
  int seeing = 0;
  for (const std::size_t pixels : sensing.fusion().counts().obstacle_pixels)
    seeing += pixels > 0 ? 1 : 0;
  EXPECT_GE(seeing, 2);
  EXPECT_GT(forbidden.count(), luts_->static_cells.count());
  EXPECT_FALSE(forbidden.test(sensing.robot_cell())) << "the robot is not its own obstacle";
}

TEST_F(SensingPipelineTest, AMissingFrameMakesTheViewUnknown) {
  SensingPipeline sensing = pipeline();
  const std::vector<double> q{0.0, 0.0, 1.0, 0.0, 0.5, 0.0};
  auto frames = sim_->render(SimScene{q, {}}, 3, 0.0);
  frames[2] = cv::Mat();
  const CellSet& forbidden = sensing.process(frames, q);
  EXPECT_FALSE(sensing.observations()[2].known);
  EXPECT_TRUE(sensing.observations()[1].known);
  EXPECT_EQ(forbidden, luts_->static_cells) << "one unknown camera is below the threshold of 2";
}

TEST_F(SensingPipelineTest, AFrameSetsUnknownViewCountsAsSeeingEverything) {
  SensingPipeline sensing = pipeline();
  const std::vector<double> q{0.0, 0.0, 1.0, 0.0, 0.5, 0.0};
  const auto images = sim_->render(SimScene{q, {}}, 5, 0.0);
  FrameSet set;
  for (std::size_t c = 0; c < images.size(); ++c) {
    set.frames.push_back(CameraFrame{cell_->cameras[c].name(), images[c], 1, 0.0,
                                     StampSource::kGrabClock, HealthReport{}});
  }
  EXPECT_EQ(sensing.process(set, q), luts_->static_cells);
  // Two cameras fail (one black, one gone): at the threshold of two they forbid what both see.
  set.frames[0].view = HealthReport{CameraFault::kBlack, "camera 'cam0': black image"};
  set.frames[3].view = HealthReport{CameraFault::kUnavailable, "camera 'cam3': cannot open"};
  set.frames[3].image = cv::Mat();
  const CellSet& forbidden = sensing.process(set, q);
  EXPECT_FALSE(sensing.observations()[0].known);
  EXPECT_FALSE(sensing.observations()[3].known);
  CellSet expected = sensing.fusion().observable(0);
  expected &= sensing.fusion().observable(3);
  expected |= luts_->static_cells;
  EXPECT_EQ(forbidden, expected);
  EXPECT_TRUE(forbidden.test(sensing.robot_cell())) << "the robot must stop: it cannot be seen";
  set.frames[1].camera = "someone else";
  EXPECT_THROW(sensing.process(set, q), std::invalid_argument);
}

TEST_F(SensingPipelineTest, ACameraExposedOutOfSyncCountsAsAnUnknownView) {
  SensingPipeline sensing = pipeline();  // sync_error_s 2 ms: +-2 ms around the median
  const std::vector<double> q{0.0, 0.0, 1.0, 0.0, 0.5, 0.0};
  const auto images = sim_->render(SimScene{q, {}}, 5, 0.0);
  FrameSet set;
  for (std::size_t c = 0; c < images.size(); ++c) {
    set.frames.push_back(CameraFrame{cell_->cameras[c].name(), images[c], 1,
                                     10.0 + 0.001 * static_cast<double>(c), StampSource::kBackend,
                                     HealthReport{}});
  }
  EXPECT_EQ(sensing.process(set, q), luts_->static_cells);
  EXPECT_EQ(sensing.out_of_sync_views(), 0u);
  set.frames[2].exposure_s = 10.030;  // a frame late
  (void)sensing.process(set, q);
  EXPECT_EQ(sensing.out_of_sync_views(), 1u);
  EXPECT_FALSE(sensing.observations()[2].known);
  EXPECT_TRUE(set.frames[2].known()) << "the caller's frame set is left as it was";
}

// The service's pipeline skips the map when the protective separation stops the robot. That must
// change nothing but the map of those frames, which must be every cell: the same frames through a
// pipeline that makes every map give the same verdicts, and the same maps whenever the robot may
// move.
TEST_F(SensingPipelineTest, SkippingTheMapWhenTheSeparationStopsChangesNothingElse) {
  test::PropertyRun run(16);
  SensingPipeline fused = pipeline();
  SensingPipeline skipping = pipeline();
  skipping.skip_map_when_too_close(true);
  ASSERT_NE(skipping.separation(), nullptr) << "the default cell checks the separation";
  std::uniform_int_distribution<CellIndex> any_cell(0, grid_->cell_count() - 1);
  std::uniform_real_distribution<double> across(-1.8, 1.8);
  int stopped = 0;
  int moving = 0;
  for (int i = 0; i < run.iterations(); ++i) {
    const auto q = test::configuration_in(*grid_, any_cell(run.rng()), run.rng());
    HumanPose person;
    person.position_m = {across(run.rng()), across(run.rng())};
    if (i % 2 == 1) {
      // Every other one in a corner, more than 2 m from the base, where the robot may often move.
      person.position_m = {
          std::copysign(1.5 + 0.3 * std::abs(person.position_m.x()) / 1.8, person.position_m.x()),
          std::copysign(1.5 + 0.3 * std::abs(person.position_m.y()) / 1.8, person.position_m.y())};
    }
    std::string scene = "person at (" + std::to_string(person.position_m.x()) + ", " +
                        std::to_string(person.position_m.y()) + "), q";
    for (const double angle : q) scene += " " + std::to_string(angle);
    SCOPED_TRACE(scene);
    const auto frames =
        sim_->render(SimScene{q, {person}}, 200U + static_cast<std::uint64_t>(i), 0.0);
    const CellSet& full = fused.process(frames, q);
    const CellSet& sent = skipping.process(frames, q);
    const SeparationVerdict& verdict = fused.separation_verdict();
    ASSERT_EQ(skipping.separation_verdict().too_close, verdict.too_close);
    ASSERT_EQ(skipping.separation_verdict().speed_limit, verdict.speed_limit);
    EXPECT_EQ(skipping.fusion().counts().obstacle_pixels, fused.fusion().counts().obstacle_pixels);
    if (verdict.too_close) {
      ++stopped;
      EXPECT_EQ(sent.count(), grid_->cell_count()) << "a stop forbids every cell";
    } else {
      ++moving;
      EXPECT_EQ(sent, full);
    }
  }
  if (run.full_length()) {
    EXPECT_GT(stopped, 0) << "no scene had someone close enough to stop the robot";
    EXPECT_GT(moving, 0) << "every scene stopped the robot";
  }
}

TEST_F(SensingPipelineTest, BadInputIsRefused) {
  SensingPipeline sensing = pipeline();
  const std::vector<double> q{0.0, 0.0, 1.0, 0.0, 0.5, 0.0};
  auto frames = sim_->render(SimScene{q, {}}, 3, 0.0);
  EXPECT_THROW(sensing.process({frames[0]}, q), std::invalid_argument);
  EXPECT_THROW(sensing.process(frames, {0.0, 0.0}), std::invalid_argument);
  EXPECT_THROW(sensing.process(frames, {9.0, 0.0, 1.0, 0.0, 0.5, 0.0}), std::out_of_range);
  EXPECT_THROW(SensingPipeline(*cell_, *grid_, *luts_, *silhouettes_, {(*reference_)[0]}, {},
                               FusionSettings{}),
               std::invalid_argument);
}

}  // namespace
}  // namespace safecell
