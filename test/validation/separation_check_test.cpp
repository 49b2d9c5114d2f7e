// The protective separation's ground truth in `safecell validate` (separation_check.hpp): a person
// placed by FCL distance near the robot and far from it, rendered by the simulated cameras; the
// scene's figures for a check that stopped the robot and for one that did not.

#include <gtest/gtest.h>

#include "safecell/cell/default_cell.hpp"
#include "safecell/robot/kinematics.hpp"
#include "safecell/sim/cell_simulation.hpp"
#include "safecell/sim/ground_truth.hpp"
#include "safecell/validation/separation_check.hpp"

namespace safecell {
namespace {

constexpr double kSeparation_m = 0.64;

class SeparationCheck : public ::testing::Test {
 protected:
  static void SetUpTestSuite() { cell_ = new CellModel(load_cell_model(default_cell())); }
  static void TearDownTestSuite() { delete cell_; }

  // A person standing at (x, y) facing the base, and the robot's distance to them (FCL).
  static SimScene scene_at(double x, double y, double& distance_m) {
    SimScene scene{std::vector<double>(cell_->robot->dof(), 0.0), {}};
    HumanPose person;
    person.position_m = Eigen::Vector2d(x, y);
    person.heading_rad = std::atan2(-y, -x);
    scene.humans.push_back(person);
    distance_m = GroundTruth(human_shapes(person))
                     .min_distance_m(collision_shapes_at(*cell_->robot, scene.q));
    return scene;
  }

  // The check's verdict: the speed it allowed (1: nothing taken off, 0: a stop) and the distance
  // it found clear.
  static SeparationFigures figures(const SimScene& scene, double speed_limit, double clear_m) {
    SimulatedCell sim = simulate_cell(*cell_, SensorSettings{});
    std::vector<cv::Mat> object_ids;
    (void)sim.render(scene, 1, 0.0, &object_ids);
    return check_separation(*cell_, scene, object_ids, cell_->camera_threshold, kSeparation_m,
                            speed_limit, clear_m);
  }

  static inline CellModel* cell_ = nullptr;
};

TEST_F(SeparationCheck, ANearPersonMustStopTheRobotAndAFarOneNeedNot) {
  // Walk out from the base along -y until the person is 0.2 .. 0.5 m, then 1.4 m or more, away.
  double near_y = 0.0;
  double far_y = 0.0;
  for (double y = -0.4; y > -1.9; y -= 0.02) {
    double d = 0.0;
    (void)scene_at(0.0, y, d);
    if (near_y == 0.0 && d > 0.2 && d < 0.5) near_y = y;
    if (d > kSeparation_m + 0.6) {
      far_y = y;
      break;
    }
  }
  ASSERT_NE(near_y, 0.0);
  ASSERT_NE(far_y, 0.0);
  double d = 0.0;
  const SimScene near = scene_at(0.0, near_y, d);
  const SeparationFigures stopped = figures(near, 0.0, 0.0);
  EXPECT_EQ(stopped.scenes, 1U);
  EXPECT_EQ(stopped.within, 1U) << "a person " << d << " m from the robot";
  EXPECT_EQ(stopped.missed, 0U);
  EXPECT_EQ(stopped.far, 0U);
  const SeparationFigures not_stopped = figures(near, 1.0, kSeparation_m);
  EXPECT_EQ(not_stopped.missed, 1U);  // the figure that fails validate
  // Slowed to a speed whose distance the person is beyond: right; within it: missed.
  const SeparationFigures slowed_enough = figures(near, 0.25, 0.15);
  EXPECT_EQ(slowed_enough.slowed, 1U);
  EXPECT_EQ(slowed_enough.missed, 0U) << "a person " << d << " m from the robot";
  EXPECT_EQ(figures(near, 0.5, 0.55).missed, 1U) << "a person " << d << " m from the robot";

  const SimScene far = scene_at(0.0, far_y, d);
  const SeparationFigures far_stopped = figures(far, 0.0, 0.0);
  EXPECT_EQ(far_stopped.within, 0U) << "a person " << d << " m from the robot";
  EXPECT_EQ(far_stopped.far, 1U);
  EXPECT_EQ(far_stopped.needless, 1U);
  EXPECT_EQ(figures(far, 1.0, kSeparation_m).needless, 0U);
  EXPECT_EQ(figures(far, 0.5, 0.4).needless, 1U);  // a needless slow-down

  SeparationFigures sum = stopped;
  sum += far_stopped;
  EXPECT_EQ(sum.scenes, 2U);
  EXPECT_DOUBLE_EQ(sum.needless_share(), 1.0);
}

}  // namespace
}  // namespace safecell
