#include "safecell/safety/safety_relation.hpp"

#include <gtest/gtest.h>

#include <limits>

#include "safecell/test/property.hpp"

namespace safecell {
namespace {

// The worked example used throughout:
//   t_s = 40 ms (25 Hz cameras), t_p = 10 ms, t_net = 2 ms, T_wd = 100 ms, t_cycle = 4 ms
//   -> reaction = 0.156 s; human 1.6 m/s.
SafetyTiming example_timing() {
  SafetyTiming timing;
  timing.delays = ReactionDelays{0.040, 0.010, 0.002, 0.100, 0.004};
  timing.human_speed_m_s = 1.6;
  return timing;
}

// l = 1 m, cells 0.1 rad wide: the farthest point travels 0.1 m per cell (below m_max = 0.18).
constexpr JointCellGeometry kArm{1.0, 0.1, 0.18, true};
// l = 0.5 m, cells 0.2 rad wide: also 0.1 m per cell.
constexpr JointCellGeometry kForearm{0.5, 0.2, 0.18, true};
// l = 2 m, cells 0.1 rad wide: the arc (0.2 m) exceeds m_max, so a cell counts as 0.18 m.
constexpr JointCellGeometry kLongArm{2.0, 0.1, 0.18, true};
constexpr JointCellGeometry kWrist{0.1, 4.0, 0.18, false};

TEST(SafetyRelation, TotalReactionAddsEveryDelay) {
  EXPECT_NEAR(total_reaction_s(example_timing().delays).value(), 0.156, 1e-15);
  ReactionDelays bad = example_timing().delays;
  bad.network_s = -0.001;
  EXPECT_EQ(total_reaction_s(bad).error(), Status::kInvalidArgument);
}

TEST(SafetyRelation, LookAheadDistance) {
  EXPECT_NEAR(look_ahead_distance_m(12, kArm).value(), 1.2, 1e-12);      // 12 x 0.1 m
  EXPECT_NEAR(look_ahead_distance_m(10, kLongArm).value(), 1.8, 1e-12);  // 10 x m_max
  EXPECT_EQ(look_ahead_distance_m(0, kArm).value(), 0.0);
}

TEST(SafetyRelation, TimeToCollision) {
  // 1.2 m / (1.0 m/s robot + 1.6 m/s human) = 0.461538 s.
  EXPECT_NEAR(time_to_collision_s(1.2, 1.0, 1.6).value(), 1.2 / 2.6, 1e-15);
  EXPECT_EQ(time_to_collision_s(1.2, 0.0, 0.0).value(), std::numeric_limits<double>::infinity());
  EXPECT_EQ(time_to_collision_s(-1.0, 1.0, 1.6).error(), Status::kInvalidArgument);
  EXPECT_EQ(time_to_collision_s(1.0, std::numeric_limits<double>::quiet_NaN(), 1.6).error(),
            Status::kInvalidArgument);
}

TEST(SafetyRelation, MinimumLookAheadWorkedExample) {
  // Joint at 1 rad/s, l = 1 m -> robot 1.0 m/s; closing speed 2.6 m/s.
  // Budget = reaction 0.156 s + stop 0.300 s = 0.456 s -> 2.6 x 0.456 = 1.1856 m
  // -> 1.1856 m / 0.1 m per cell = 11.856 -> 12 cells.
  EXPECT_EQ(min_look_ahead_cells(kArm, JointMotion{1.0, 0.300}, example_timing()).value(), 12u);
  // Same motion on the long arm: robot 2.0 m/s, closing 3.6 m/s, 3.6 x 0.456 = 1.6416 m
  // -> / 0.18 m per cell = 9.12 -> 10 cells.
  EXPECT_EQ(min_look_ahead_cells(kLongArm, JointMotion{1.0, 0.300}, example_timing()).value(), 10u);
  // A still joint or a swept joint needs no look-ahead.
  EXPECT_EQ(min_look_ahead_cells(kArm, JointMotion{0.0, 0.300}, example_timing()).value(), 0u);
  EXPECT_EQ(min_look_ahead_cells(kWrist, JointMotion{3.0, 0.100}, example_timing()).value(), 0u);
}

TEST(SafetyRelation, MaximumSafeSpeedWorkedExample) {
  // 12 free cells = 1.2 m; 1.2 m / 0.456 s = 2.631579 m/s closing; minus the human's 1.6 m/s
  // leaves 1.031579 m/s for the robot; / l = 1 m -> 1.031579 rad/s.
  EXPECT_NEAR(max_safe_speed_rad_s(12, kArm, 0.300, example_timing()).value(), 1.2 / 0.456 - 1.6,
              1e-12);
  // 5 free cells = 0.5 m: 0.5 / 0.456 = 1.096 m/s is below the human's speed: stand still.
  EXPECT_EQ(max_safe_speed_rad_s(5, kArm, 0.300, example_timing()).value(), 0.0);
  EXPECT_EQ(max_safe_speed_rad_s(1, kWrist, 0.100, example_timing()).value(),
            std::numeric_limits<double>::infinity());
}

TEST(SafetyRelation, MaximumSpeedAndMinimumLookAheadAreInverses) {
  test::PropertyRun run(2000);
  std::uniform_real_distribution<double> lever(0.1, 2.0), width(0.01, 0.5), speed(0.01, 3.0),
      stop(0.0, 0.6), delay(0.0, 0.05);
  for (int i = 0; i < run.iterations(); ++i) {
    const JointCellGeometry cell{lever(run.rng()), width(run.rng()), 0.18, true};
    SafetyTiming timing;
    timing.delays = ReactionDelays{delay(run.rng()), delay(run.rng()), delay(run.rng()),
                                   delay(run.rng()), delay(run.rng())};
    const JointMotion motion{speed(run.rng()), stop(run.rng())};
    const std::uint32_t cells = min_look_ahead_cells(cell, motion, timing).value();
    // With that look-ahead the speed is allowed; with one cell less it is not.
    const double allowed = max_safe_speed_rad_s(cells, cell, motion.stop_time_s, timing).value();
    EXPECT_GE(allowed, motion.speed_rad_s * (1.0 - 1e-12)) << "iteration " << i;
    if (cells > 0) {
      const double fewer =
          max_safe_speed_rad_s(cells - 1, cell, motion.stop_time_s, timing).value();
      EXPECT_LT(fewer, motion.speed_rad_s * (1.0 + 1e-12)) << "iteration " << i;
    }
  }
}

TEST(SafetyRelation, CriticalJointWorkedExample) {
  // Arm: 12 free cells, 1 rad/s, stop 0.3 s: t_c = 1.2 / 2.6 = 0.461538 s,
  //      slack = 0.461538 - (0.156 + 0.300) = 0.005538 s.
  // Forearm: 10 free cells (1.0 m), 2 rad/s x 0.5 m = 1.0 m/s, stop 0.2 s: t_c = 1.0 / 2.6 =
  //      0.384615 s, slack = 0.384615 - 0.356 = 0.028615 s.
  // Wrist (swept) and a still joint do not compete.
  const JointCellGeometry cells[] = {kArm, kForearm, kWrist, kArm};
  const JointMotion motions[] = {{1.0, 0.300}, {2.0, 0.200}, {5.0, 0.050}, {0.0, 0.300}};
  const std::uint32_t free_cells[] = {12, 10, 0, 1};
  const auto critical = critical_joint(cells, motions, free_cells, 4, example_timing());
  ASSERT_TRUE(critical.ok());
  EXPECT_EQ(critical.value().joint, 0);
  EXPECT_NEAR(critical.value().time_to_collision_s, 1.2 / 2.6, 1e-12);
  EXPECT_NEAR(critical.value().slack_s, 1.2 / 2.6 - 0.456, 1e-12);

  // Two fewer free cells for the arm: t_c = 1.0 / 2.6 = 0.3846 s < 0.456 s: violated.
  const std::uint32_t closer[] = {10, 10, 0, 1};
  const auto violated = critical_joint(cells, motions, closer, 4, example_timing());
  EXPECT_EQ(violated.value().joint, 0);
  EXPECT_LT(violated.value().slack_s, 0.0);
}

TEST(SafetyRelation, NoCriticalJointWhenNothingMoves) {
  const JointCellGeometry cells[] = {kArm, kWrist};
  const JointMotion motions[] = {{0.0, 0.3}, {2.0, 0.1}};
  const std::uint32_t free_cells[] = {3, 0};
  EXPECT_EQ(critical_joint(cells, motions, free_cells, 2, example_timing()).value().joint,
            kNoCriticalJoint);
}

TEST(SafetyRelation, InvalidParametersGiveAnErrorValue) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  SafetyTiming timing = example_timing();
  EXPECT_EQ(min_look_ahead_cells(kArm, JointMotion{nan, 0.3}, timing).error(),
            Status::kInvalidArgument);
  EXPECT_EQ(min_look_ahead_cells(kArm, JointMotion{1.0, -0.3}, timing).error(),
            Status::kInvalidArgument);
  EXPECT_EQ(
      min_look_ahead_cells(JointCellGeometry{1.0, 0.0, 0.18, true}, JointMotion{1.0, 0.3}, timing)
          .error(),
      Status::kInvalidArgument);
  EXPECT_EQ(max_safe_speed_rad_s(3, kArm, inf, timing).error(), Status::kInvalidArgument);
  timing.human_speed_m_s = -1.6;
  EXPECT_EQ(max_safe_speed_rad_s(3, kArm, 0.3, timing).error(), Status::kInvalidArgument);
  timing = example_timing();
  timing.delays.watchdog_s = nan;
  EXPECT_EQ(min_look_ahead_cells(kArm, JointMotion{1.0, 0.3}, timing).error(),
            Status::kInvalidArgument);
  // An absurdly slow sensor: the look-ahead would not fit 32 bits.
  timing = example_timing();
  timing.delays.sensor_period_s = 1e12;
  EXPECT_EQ(min_look_ahead_cells(kArm, JointMotion{1.0, 0.3}, timing).error(), Status::kOverflow);
  const JointMotion motions[] = {{1.0, 0.3}};
  const std::uint32_t free_cells[] = {3};
  EXPECT_EQ(critical_joint(nullptr, motions, free_cells, 1, example_timing()).error(),
            Status::kInvalidArgument);
  EXPECT_EQ(critical_joint(&kArm, motions, free_cells, kMaxJoints + 1, example_timing()).error(),
            Status::kInvalidArgument);
}

TEST(SafetyRelation, GeometryComesFromTheGrid) {
  GridSpec spec;
  spec.m_max_m = 0.18;
  spec.joint_count = 2;
  spec.joints[0] = JointSpec{-1.0, 1.0, 1.45, true};
  spec.joints[1] = JointSpec{-2.0, 2.0, 0.1, false};
  const CspaceGrid grid = CspaceGrid::create(spec).value();
  const JointCellGeometry first = joint_cell_geometry(grid, 0);
  EXPECT_EQ(first.l_m, 1.45);
  EXPECT_EQ(first.cell_width_rad, grid.cell_width_rad(0));
  EXPECT_EQ(first.m_max_m, 0.18);
  EXPECT_TRUE(first.discretised);
  EXPECT_FALSE(joint_cell_geometry(grid, 1).discretised);
}

}  // namespace
}  // namespace safecell
