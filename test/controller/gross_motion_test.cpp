// The safe gross-motion service on the simulated robot: it reaches a goal over free cells without
// ever standing in a forbidden one, goes round an obstacle, and when no path exists it holds the
// robot, keeps trying with each new map, and gives up with the blocking cell and joint.

#include "safecell/controller/gross_motion.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "safecell/controller/host/planner_memory.hpp"
#include "safecell/controller/host/simulated_robot.hpp"
#include "store_receiver.hpp"

namespace safecell {
namespace {

using test::Words;

class GrossMotionTest : public ::testing::Test {
 protected:
  GrossMotionTest()
      : grid_(CspaceGrid::create(spec()).value()),
        layout_(PlannerLayout::for_grid(grid_.cell_count())),
        memory_(layout_),
        planner_(grid_, layout_, memory_.memory()),
        motion_(grid_, planner_, motion_config()),
        robot_(robot_config()),
        store_(grid_.cell_count(), 64) {}

  static GridSpec spec() {
    GridSpec grid;
    grid.m_max_m = 0.1;
    grid.joint_count = 3;
    for (std::uint32_t j = 0; j < 3; ++j) grid.joints[j] = {-2.0, 2.0, 0.5, true};
    return grid;
  }
  static GrossMotionConfig motion_config() {
    GrossMotionConfig config;
    for (std::uint32_t j = 0; j < 3; ++j) {
      config.max_speed_rad_s[j] = 1.0;
      config.accel_rad_s2[j] = 4.0;
    }
    config.give_up_s = 1.0;
    return config;
  }
  static SimulatedRobotConfig robot_config() {
    SimulatedRobotConfig config;
    config.joint_count = 3;
    for (std::uint32_t j = 0; j < 3; ++j) config.joints[j] = {-2.0, 2.0, 1.0, 4.0, 4.0};
    config.start_rad[0] = -1.5;
    return config;
  }
  // A new map version (a keyframe) for the service to see.
  void hold_map(const Words& map) {
    const MapOffer offer = store_.offer_all(
        test::update_of(nullptr, 0, map, ++map_version_, grid_.cell_count(), 1024));
    ASSERT_EQ(offer.outcome, MapOutcome::kApplied);
  }
  CellIndex robot_cell() {
    const RobotJoints joints = robot_.read();
    JointAngles q;
    for (std::uint32_t j = 0; j < 3; ++j) q.rad[j] = joints.position_rad[j];
    return grid_.cell_containing(q).value();
  }
  // Runs the service on the robot for up to `seconds`; false if it ever stood in a forbidden cell.
  bool run(double seconds, const Words& map) {
    for (int step = 0; step < static_cast<int>(seconds / 0.004); ++step) {
      double planned[kMaxJoints] = {};
      motion_.plan_velocity(robot_.read(), store_.store().view(), map_version_, robot_.time_ns(),
                            planned);
      (void)robot_.command_joint_velocity(planned, 3);
      robot_.step(0.004);
      if (cell_bits::test(map.data(), robot_cell())) return false;
      const MotionStatus status = motion_.progress().status;
      if (status == MotionStatus::kArrived || status == MotionStatus::kFailed) break;
    }
    return true;
  }

  CspaceGrid grid_;
  PlannerLayout layout_;
  PlannerMemoryHost memory_;
  GridPlanner planner_;
  GrossMotion motion_;
  SimulatedRobot robot_;
  StoreReceiver store_;
  std::uint64_t map_version_ = 0;
};

TEST_F(GrossMotionTest, ReachesTheGoalOnAFreeMap) {
  const Words map(cell_bits::words_for(grid_.cell_count()), 0);
  hold_map(map);
  JointAngles goal;
  goal.rad[0] = 1.2;
  goal.rad[1] = -0.7;
  goal.rad[2] = 0.4;
  ASSERT_EQ(motion_.move_to(goal), Status::kOk);
  ASSERT_TRUE(run(20.0, map));
  EXPECT_EQ(motion_.progress().status, MotionStatus::kArrived);
  const RobotJoints joints = robot_.read();
  for (std::uint32_t j = 0; j < 3; ++j) EXPECT_NEAR(joints.position_rad[j], goal.rad[j], 0.01);
}

TEST_F(GrossMotionTest, GoesRoundAWallThroughItsGap) {
  // A wall across joint 0 at its middle, open only at joint 1's upper end.
  Words map(cell_bits::words_for(grid_.cell_count()), 0);
  const std::uint32_t middle = grid_.cells_along(0) / 2;
  for (CellIndex c = 0; c < grid_.cell_count(); ++c) {
    const GridCoords at = grid_.coords_of(c).value();
    if (at.along[0] == middle && at.along[1] + 2 < grid_.cells_along(1)) {
      cell_bits::set(map.data(), c);
    }
  }
  hold_map(map);
  JointAngles goal;
  goal.rad[0] = 1.5;
  ASSERT_EQ(motion_.move_to(goal), Status::kOk);
  ASSERT_TRUE(run(30.0, map)) << "stood in a forbidden cell";
  EXPECT_EQ(motion_.progress().status, MotionStatus::kArrived);
  EXPECT_GE(motion_.progress().plans, 1u);
  EXPECT_GT(motion_.progress().path_length, grid_.cells_along(0) / 2 + grid_.cells_along(1) / 2)
      << "the path goes round by the gap";
}

TEST_F(GrossMotionTest, WithoutAPathItHoldsThenGivesUpNamingTheBlock) {
  Words map(cell_bits::words_for(grid_.cell_count()), 0);
  const std::uint32_t middle = grid_.cells_along(0) / 2;
  for (CellIndex c = 0; c < grid_.cell_count(); ++c) {
    if (grid_.coords_of(c).value().along[0] == middle) cell_bits::set(map.data(), c);
  }
  hold_map(map);
  JointAngles goal;
  goal.rad[0] = 1.5;
  ASSERT_EQ(motion_.move_to(goal), Status::kOk);
  ASSERT_TRUE(run(0.2, map));
  EXPECT_EQ(motion_.progress().status, MotionStatus::kBlocked);
  EXPECT_FALSE(robot_.moving());
  // It tries again with each new map and fails after give_up_s.
  for (int i = 0; i < 30 && motion_.progress().status != MotionStatus::kFailed; ++i) {
    hold_map(map);
    ASSERT_TRUE(run(0.05, map));
  }
  const MotionProgress& progress = motion_.progress();
  EXPECT_EQ(progress.status, MotionStatus::kFailed);
  EXPECT_GT(progress.plans, 2u);
  EXPECT_EQ(progress.last_plan.status, PlanStatus::kNoPath);
  ASSERT_TRUE(progress.last_plan.has_blocking_cell);
  EXPECT_EQ(progress.last_plan.blocked_joint, 0);
  EXPECT_TRUE(cell_bits::test(map.data(), progress.last_plan.blocking_cell));
}

// A goal a few cells away in free space: the local planner goes straight, without a search.
TEST_F(GrossMotionTest, ANearGoalIsReachedOnAStraightLine) {
  const Words map(cell_bits::words_for(grid_.cell_count()), 0);
  hold_map(map);
  JointAngles goal;
  goal.rad[0] = -1.2;
  goal.rad[1] = 0.3;
  ASSERT_EQ(motion_.move_to(goal), Status::kOk);
  ASSERT_TRUE(run(10.0, map));
  EXPECT_EQ(motion_.progress().status, MotionStatus::kArrived);
  EXPECT_TRUE(motion_.progress().direct);
  EXPECT_EQ(motion_.progress().plans, 0u) << "no search";
}

// The same near goal with a forbidden cell on the straight line: the local planner declines and
// the search goes round it.
TEST_F(GrossMotionTest, TheLocalPlannerDeclinesWhenACellBetweenIsForbidden) {
  Words map(cell_bits::words_for(grid_.cell_count()), 0);
  JointAngles between;
  between.rad[0] = -1.35;
  between.rad[1] = 0.15;
  cell_bits::set(map.data(), grid_.cell_containing(between).value());
  hold_map(map);
  JointAngles goal;
  goal.rad[0] = -1.2;
  goal.rad[1] = 0.3;
  ASSERT_EQ(motion_.move_to(goal), Status::kOk);
  ASSERT_TRUE(run(10.0, map)) << "stood in a forbidden cell";
  EXPECT_EQ(motion_.progress().status, MotionStatus::kArrived);
  EXPECT_FALSE(motion_.progress().direct);
  EXPECT_GE(motion_.progress().plans, 1u);
}

TEST_F(GrossMotionTest, RefusesAGoalOutsideTheGrid) {
  JointAngles goal;
  goal.rad[1] = 3.0;
  EXPECT_EQ(motion_.move_to(goal), Status::kOutOfRange);
  goal.rad[1] = NAN;
  EXPECT_EQ(motion_.move_to(goal), Status::kInvalidArgument);
}

}  // namespace
}  // namespace safecell
