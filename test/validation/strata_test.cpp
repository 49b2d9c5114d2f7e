// The scene and configuration strata of `safecell validate`: each generator places what it says,
// checked with the ground truth (FCL distances, the renderer's object ids).

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "model_fixture.hpp"
#include "safecell/robot/kinematics.hpp"
#include "safecell/sim/cell_simulation.hpp"
#include "safecell/sim/ground_truth.hpp"
#include "safecell/test/property.hpp"
#include "safecell/validation/configuration_strata.hpp"
#include "safecell/validation/scene_check.hpp"
#include "safecell/validation/scene_strata.hpp"

namespace safecell {
namespace {

class StrataTest : public ::testing::Test {
 protected:
  StrataTest() : sim_(simulate_cell(cell_, SensorSettings{})) {}

  std::vector<StratifiedScene> scenes(SceneStratum stratum, test::PropertyRun& run) {
    std::vector<StratifiedScene> made;
    for (int i = 0; i < run.iterations(); ++i) {
      made.push_back(make_scene(stratum, cell_, grid_, SceneLimits{}, run.rng()));
      const StratifiedScene& placed = made.back();
      EXPECT_EQ(placed.stratum, stratum) << "iteration " << i;
      expect_room(placed.scene, i);
    }
    return made;
  }

  // Nobody stands in the robot, a static obstacle or another body.
  void expect_room(const SimScene& scene, int iteration) {
    const auto robot = collision_shapes_at(*cell_.robot, scene.q);
    std::vector<std::vector<PlacedShape>> bodies;
    for (const auto& human : scene.humans) bodies.push_back(human_shapes(human));
    for (const auto& object : scene.objects) bodies.push_back({object});
    for (std::size_t b = 0; b < bodies.size(); ++b) {
      EXPECT_FALSE(GroundTruth(bodies[b]).collides(robot)) << "body " << b << ", " << iteration;
      EXPECT_FALSE(GroundTruth(cell_.obstacles).collides(bodies[b]))
          << "body " << b << ", iteration " << iteration;
      for (std::size_t other = 0; other < b; ++other) {
        EXPECT_FALSE(GroundTruth(bodies[other]).collides(bodies[b]))
            << "bodies " << other << " and " << b << ", iteration " << iteration;
      }
    }
  }

  // In how many cameras some of human 0's own pixels show a body of `kind` instead.
  int cameras_hiding_human(const SimScene& scene, BodyKind kind) {
    std::vector<cv::Mat> ids;
    (void)sim_.render(scene, 1, 0.0, &ids);
    const BodyCode human = body_code(BodyKind::kHuman, 0);
    std::vector<SurfaceMesh> own;
    for (const auto& surface : sim_.moving_surfaces(scene)) {
      if (surface.body == human) own.push_back(surface);
    }
    int hiding = 0;
    for (std::size_t c = 0; c < sim_.camera_count(); ++c) {
      const cv::Mat covered = sim_.coverage(c, own);
      int hidden = 0;
      for (int y = 0; y < covered.rows; ++y) {
        for (int x = 0; x < covered.cols; ++x) {
          hidden +=
              covered.at<std::uint8_t>(y, x) != 0 && body_kind(ids[c].at<BodyCode>(y, x)) == kind;
        }
      }
      hiding += hidden > 0 ? 1 : 0;
    }
    return hiding;
  }

  CellModel cell_ = test::coarse_default_cell();
  CspaceGrid grid_ = make_grid(cell_.config);
  SimulatedCell sim_;
};

TEST_F(StrataTest, AgainstTheArmIsWithinACoupleOfCentimetres) {
  test::PropertyRun run(20);
  for (const auto& placed : scenes(SceneStratum::kAgainstArm, run)) {
    ASSERT_EQ(placed.scene.humans.size(), 1U);
    const double gap_m = GroundTruth(human_shapes(placed.scene.humans[0]))
                             .min_distance_m(collision_shapes_at(*cell_.robot, placed.scene.q));
    EXPECT_GT(gap_m, 0.0);
    EXPECT_LT(gap_m, 0.05) << "q[0] " << placed.scene.q[0];
  }
}

TEST_F(StrataTest, BehindTheArmIsPartlyHiddenByItInMostScenes) {
  test::PropertyRun run(48);
  int hidden = 0;
  for (const auto& placed : scenes(SceneStratum::kBehindArm, run)) {
    hidden += cameras_hiding_human(placed.scene, BodyKind::kRobot) > 0 ? 1 : 0;
  }
  // About 9 scenes in 10 are (361 of 400 measured; behind an obstacle more), so two thirds of 48
  // fails about twice in a million runs; uniform scenes (139 of 300 measured) pass it about 3
  // times in 1,000. A replay of one scene is not "most".
  if (run.full_length()) {
    EXPECT_GE(3 * hidden, 2 * run.iterations()) << hidden << " of " << run.iterations();
  }
}

TEST_F(StrataTest, BehindAStaticObstacleIsPartlyHiddenByItInMostScenes) {
  test::PropertyRun run(12);
  int hidden = 0;
  for (const auto& placed : scenes(SceneStratum::kBehindStaticObstacle, run)) {
    hidden += cameras_hiding_human(placed.scene, BodyKind::kStaticObstacle) > 0 ? 1 : 0;
  }
  EXPECT_GE(2 * hidden, run.iterations()) << hidden << " of " << run.iterations();
}

TEST_F(StrataTest, ReachingPeopleFaceTheArmWithAnArmOut) {
  test::PropertyRun run(20);
  for (const auto& placed : scenes(SceneStratum::kReaching, run)) {
    ASSERT_EQ(placed.scene.humans.size(), 1U);
    const HumanPose& pose = placed.scene.humans[0];
    EXPECT_GT(pose.right_arm_reach_rad, 0.5);
    const auto shapes = human_shapes(pose);
    // The reaching hand is ahead of the shoulders, in the direction the figure faces.
    const Eigen::Vector2d facing(std::cos(pose.heading_rad), std::sin(pose.heading_rad));
    const Eigen::Vector2d hand =
        shapes[static_cast<std::size_t>(HumanPart::kRightForearm)].pose.translation().head<2>();
    EXPECT_GT((hand - pose.position_m).dot(facing), 0.2);
    EXPECT_LT(GroundTruth(shapes).min_distance_m(collision_shapes_at(*cell_.robot, placed.scene.q)),
              1.2);
  }
}

TEST_F(StrataTest, BoxesStandOnTheFloorAndOnTheWorkbench) {
  test::PropertyRun run(10);
  int on_bench = 0;
  const double bench_top_m = cell_.obstacles.at(0).pose.translation().z() + 0.4;
  for (const auto& placed : scenes(SceneStratum::kBoxes, run)) {
    EXPECT_GE(placed.scene.objects.size(), 1U);
    for (const auto& object : placed.scene.objects) {
      const double bottom_m =
          object.pose.translation().z() - std::get<Box>(object.shape).size_m.z() / 2.0;
      EXPECT_TRUE(std::abs(bottom_m) < 1e-9 || std::abs(bottom_m - bench_top_m) < 2e-3) << bottom_m;
      on_bench += std::abs(bottom_m - bench_top_m) < 2e-3 ? 1 : 0;
    }
  }
  if (run.full_length()) {
    EXPECT_GT(on_bench, 0);
  }
}

TEST_F(StrataTest, UniformScenesHavePeopleAndAtMostTheBoxesAsked) {
  test::PropertyRun run(10);
  for (const auto& placed : scenes(SceneStratum::kUniform, run)) {
    EXPECT_GE(placed.scene.humans.size(), 1U);
    EXPECT_LE(placed.scene.humans.size(), 2U);
    EXPECT_LE(placed.scene.objects.size(), 1U);
  }
}

TEST_F(StrataTest, NearRobotConfigurationsStayWithinTwoCellsOfTheRobot) {
  test::PropertyRun run(200);
  const SimScene scene = make_scene(SceneStratum::kUniform, cell_, grid_, {}, run.rng()).scene;
  const GridCoords robot = grid_.coords_of(cell_of(grid_, scene.q)).value();
  for (int i = 0; i < run.iterations(); ++i) {
    const auto q =
        sample_configuration(ConfigurationStratum::kNearRobot, grid_, scene, 0, run.rng());
    const GridCoords near = grid_.coords_of(cell_of(grid_, q)).value();
    for (std::uint32_t j = 0; j < grid_.joint_count(); ++j) {
      EXPECT_LE(std::abs(static_cast<int>(near.along[j]) - static_cast<int>(robot.along[j])),
                kNearRobotCells)
          << "joint " << j << ", iteration " << i;
    }
  }
}

TEST_F(StrataTest, TowardsBodyConfigurationsTurnJointOneToIt) {
  test::PropertyRun run(50);
  SimScene scene{std::vector<double>(grid_.joint_count(), 0.0), {}};
  HumanPose person;
  person.position_m = {0.0, 1.5};
  scene.humans.push_back(person);
  for (int i = 0; i < run.iterations(); ++i) {
    const auto q =
        sample_configuration(ConfigurationStratum::kTowardsBody, grid_, scene, 0, run.rng());
    EXPECT_NEAR(q[0], std::numbers::pi / 2.0, 0.3 + 1e-12);
  }
}

}  // namespace
}  // namespace safecell
