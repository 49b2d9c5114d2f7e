// The safety cycle's responses: held before a session and a verified map; moving on a free map;
// category 2 stops from the look-ahead that lift when the cells ahead are free again; category 1
// stops latched until acknowledged for every fault (the map too old, a hash mismatch, too few
// cameras, a late cycle).

#include "safecell/controller/safety_cycle.hpp"

#include <gtest/gtest.h>

#include <vector>

#include "safecell/controller/boot_counter_entropy.hpp"
#include "safecell/controller/host/map_store_memory.hpp"
#include "safecell/controller/host/simulated_robot.hpp"
#include "scripted_coprocessor.hpp"

namespace safecell {
namespace {

using Words = std::vector<std::uint64_t>;
constexpr std::uint64_t kMs = 1'000'000;
constexpr std::uint64_t kLuts = 0x1075;

GridSpec spec() {
  GridSpec grid;
  grid.m_max_m = 0.1;
  grid.joint_count = 3;
  for (std::uint32_t j = 0; j < 3; ++j) grid.joints[j] = {-2.0, 2.0, 0.5, true};
  return grid;
}

SimulatedRobotConfig robot_config() {
  SimulatedRobotConfig config;
  config.joint_count = 3;
  for (std::uint32_t j = 0; j < 3; ++j) config.joints[j] = {-2.0, 2.0, 1.0, 4.0, 4.0};
  return config;
}

class SafetyCycleTest : public ::testing::Test {
 protected:
  explicit SafetyCycleTest(std::uint32_t min_cameras = 1, bool look_ahead_off = false)
      : grid_(CspaceGrid::create(spec()).value()),
        robot_(robot_config()),
        clock_(robot_),
        store_(MapStoreLayout::of(grid_.cell_count())),
        link_(link_config(), port_, store_.store(), entropy_),
        watchdog_({3 * kMs, 5 * kMs, 2 * kMs}),
        cycle_(grid_, cycle_config(min_cameras, look_ahead_off), robot_, clock_, link_,
               store_.store(), watchdog_),
        coprocessor_(grid_.fingerprint(), kLuts, 0x5E55, grid_.cell_count()),
        free_(cell_bits::words_for(grid_.cell_count()), 0) {
    robot_.set_time_ns(1'000'000'000);
    planned_[0] = 0.5;
  }

  ControllerLinkConfig link_config() const {
    ControllerLinkConfig config;
    config.grid_fingerprint = grid_.fingerprint();
    config.lut_fingerprint = kLuts;
    return config;
  }
  static SafetyCycleConfig cycle_config(std::uint32_t min_cameras, bool look_ahead_off) {
    SafetyCycleConfig config;
    config.look_ahead_switched_off = look_ahead_off;
    config.look_ahead.stop = SimulatedRobot::measure_stop_model(robot_config());
    config.min_healthy_cameras = min_cameras;
    return config;
  }
  std::uint64_t now() const { return robot_.time_ns(); }
  // One cycle, then 4 ms of the robot (or `step_ms`).
  const CycleReport& cycle(double step_ms = 4.0) {
    const CycleReport& report = cycle_.run(planned_, true);
    robot_.step(step_ms * 1e-3);
    return report;
  }
  void send_map(const Words& map, bool wrong_hash = false) {
    const Words* base = version_ == 0 ? nullptr : &held_;
    port_.inbox.push_back(coprocessor_.update(base, version_, map, version_ + 1, now() - 10 * kMs,
                                              now(), wrong_hash));
    if (!wrong_hash) {
      ++version_;
      held_ = map;
    }
  }
  void open_session() {
    port_.inbox.push_back(coprocessor_.handshake(now()));
    (void)cycle();
    port_.inbox.push_back(coprocessor_.answer(port_.sent.back(), now()));
    (void)cycle();
  }
  // Cycles with a fresh map every 8th, for `count` cycles; the last report.
  CycleReport run_with_maps(int count, const Words& map) {
    CycleReport last;
    for (int i = 0; i < count; ++i) {
      if (i % 8 == 0) send_map(map);
      last = cycle();
    }
    return last;
  }

  CspaceGrid grid_;
  SimulatedRobot robot_;
  SimulatedClock clock_;
  HostMapStore store_;
  BootCounterEntropy entropy_{1};
  test::MemoryPort port_;
  ControllerLink link_;
  Watchdog watchdog_;
  SafetyCycle cycle_;
  test::ScriptedCoprocessor coprocessor_;
  Words free_;
  Words held_;
  std::uint64_t version_ = 0;
  double planned_[kMaxJoints] = {};
};

// A cycle does one bounded slice of the link's map work; service_link() does the rest in the time
// between cycles, up to its deadline, and stops when the link is idle.
TEST_F(SafetyCycleTest, BetweenCyclesTheLinkWorksOnInSlicesUntilIdleOrTheDeadline) {
  open_session();
  Words striped(cell_bits::words_for(grid_.cell_count()), 0);
  for (CellIndex c = 0; c + 2 < grid_.cell_count(); c += 16) {
    cell_bits::set_range(striped.data(), c, c + 2);
  }
  send_map(striped);  // a keyframe of about 500 runs: several slices of work
  (void)cycle();
  EXPECT_EQ(store_.store().version(), 0u);
  EXPECT_TRUE(store_.store().busy());
  EXPECT_EQ(cycle_.service_link(now()), 0);  // no time left before the next cycle: no slice
  EXPECT_EQ(store_.store().version(), 0u);
  const int slices = cycle_.service_link(now() + 2 * kMs);
  EXPECT_GT(slices, 3);
  EXPECT_EQ(store_.store().version(), 1u);
  EXPECT_FALSE(store_.store().busy());
  EXPECT_EQ(cycle_.service_link(now() + 2 * kMs), 1);  // idle: one poll finds nothing
  EXPECT_EQ(cycle().state, CycleState::kMoving);
}

TEST_F(SafetyCycleTest, HeldUntilASessionAndAVerifiedKeyframe) {
  EXPECT_EQ(cycle().state, CycleState::kWaiting);
  open_session();
  EXPECT_EQ(cycle().state, CycleState::kWaiting);
  EXPECT_FALSE(robot_.moving());
  const CycleReport moving = run_with_maps(40, free_);
  EXPECT_EQ(moving.state, CycleState::kMoving);
  EXPECT_TRUE(robot_.moving());
}

TEST_F(SafetyCycleTest, AMapThatGetsTooOldStopsTheRobotUntilAcknowledged) {
  open_session();
  ASSERT_EQ(run_with_maps(40, free_).state, CycleState::kMoving);
  CycleReport report;
  for (int i = 0; i < 30; ++i) report = cycle();  // 120 ms without a map: beyond T_wd
  EXPECT_EQ(report.state, CycleState::kFault);
  EXPECT_EQ(report.fault, CycleFault::kLink);
  EXPECT_EQ(report.link_block, LinkBlock::kMapTooOld);
  EXPECT_EQ(report.stop_category, StopCategory::kCategory1);
  EXPECT_EQ(run_with_maps(16, free_).state, CycleState::kFault) << "latched";
  cycle_.acknowledge();
  EXPECT_NE(run_with_maps(200, free_).state, CycleState::kFault);
  EXPECT_TRUE(robot_.powered());
  EXPECT_TRUE(robot_.moving());
}

// The drives come back after a category-1 stop: once power is restored, the next command (which
// reaches the drives an actuation delay later) moves the robot again.
TEST(SimulatedRobotPower, ACommandAfterRestoredPowerMovesTheRobot) {
  SimulatedRobot robot(robot_config());
  const double velocity[3] = {0.5, 0.0, 0.0};
  robot.command_speed_scale(1.0);
  (void)robot.command_joint_velocity(velocity, 3);
  robot.step(0.5);
  ASSERT_TRUE(robot.moving());
  robot.stop(StopCategory::kCategory1);
  robot.step(1.0);
  ASSERT_FALSE(robot.moving());
  ASSERT_FALSE(robot.powered());
  ASSERT_TRUE(robot.restore_power());
  robot.step(0.004);  // a cycle passes before the next command
  robot.command_speed_scale(1.0);
  (void)robot.command_joint_velocity(velocity, 3);
  robot.step(0.1);
  EXPECT_TRUE(robot.powered());
  EXPECT_TRUE(robot.moving());
}

TEST_F(SafetyCycleTest, AHashMismatchStopsLatched) {
  open_session();
  ASSERT_EQ(run_with_maps(40, free_).state, CycleState::kMoving);
  send_map(free_, true);
  const CycleReport report = cycle();
  EXPECT_EQ(report.state, CycleState::kFault);
  EXPECT_EQ(report.fault, CycleFault::kMapRefused);
  EXPECT_EQ(report.stop_category, StopCategory::kCategory1);
}

// The cells ahead of joint 0 forbidden, from the robot's cell on.
Words blocked_ahead(const CspaceGrid& grid, SimulatedRobot& robot, const Words& free) {
  JointAngles here;
  const RobotJoints joints = robot.read();
  for (std::uint32_t j = 0; j < 3; ++j) here.rad[j] = joints.position_rad[j];
  const GridCoords at = grid.coords_containing(here).value();
  Words blocked = free;
  for (CellIndex c = 0; c < grid.cell_count(); ++c) {
    if (grid.coords_of(c).value().along[0] > at.along[0] + 1) cell_bits::set(blocked.data(), c);
  }
  return blocked;
}

class SafetyCycleCamerasTest : public SafetyCycleTest {
 protected:
  // The scripted cell's 4 cameras must all be healthy.
  SafetyCycleCamerasTest() : SafetyCycleTest(test::ScriptedCoprocessor::kCameras) {}
};

TEST_F(SafetyCycleCamerasTest, TooFewHealthyCamerasStopLatched) {
  open_session();
  ASSERT_EQ(run_with_maps(16, free_).state, CycleState::kMoving);  // the control: 4 of 4
  coprocessor_.set_healthy_cameras(3);
  const CycleReport report = run_with_maps(250, free_);  // 1 s: long enough to stand still
  EXPECT_EQ(report.state, CycleState::kFault);
  EXPECT_EQ(report.fault, CycleFault::kCameras);
  EXPECT_EQ(report.healthy_cameras, 3U);
  EXPECT_FALSE(robot_.moving());
}

class SafetyCycleMoreCamerasThanTheCellTest : public SafetyCycleTest {
 protected:
  SafetyCycleMoreCamerasThanTheCellTest()
      : SafetyCycleTest(test::ScriptedCoprocessor::kCameras + 1) {}
};

// A controller file asking more healthy cameras than the cell has can never be met: it is named
// as the configuration fault it is, not as cameras failing.
TEST_F(SafetyCycleMoreCamerasThanTheCellTest, IsAConfigurationFaultNamingTheCount) {
  open_session();
  const CycleReport report = run_with_maps(16, free_);
  EXPECT_EQ(report.state, CycleState::kFault);
  EXPECT_EQ(report.fault, CycleFault::kCameraCount);
  EXPECT_EQ(report.camera_count, 4U);
  EXPECT_FALSE(robot_.moving());
}

TEST_F(SafetyCycleTest, ALateCycleIsAWatchdogFault) {
  open_session();
  ASSERT_EQ(run_with_maps(40, free_).state, CycleState::kMoving);
  (void)cycle(12.0);  // the next cycle starts 12 ms later: outside the 3..5 ms window
  const CycleReport report = cycle();
  EXPECT_EQ(report.state, CycleState::kFault);
  EXPECT_EQ(report.fault, CycleFault::kWatchdog);
}

// The budget covers the cycle's work up to the robot's command; the report after it is I/O (on a
// host a loopback send can keep the thread for milliseconds). A slow send is no overrun; the
// lateness it causes is the window's to judge.
TEST_F(SafetyCycleTest, TheBudgetEndsAtTheCommand) {
  open_session();
  ASSERT_EQ(run_with_maps(40, free_).state, CycleState::kMoving);
  port_.on_send = [this] { robot_.step(3e-3); };  // every send keeps the thread 3 ms (budget 2)
  const CycleReport slow_report = cycle(1.0);     // the next cycle still starts 4 ms after
  EXPECT_EQ(slow_report.state, CycleState::kMoving);
  EXPECT_EQ(slow_report.watchdog_fault, WatchdogFault::kNone);
  port_.on_send = nullptr;
  EXPECT_EQ(cycle().state, CycleState::kMoving);
}

TEST_F(SafetyCycleTest, ALookAheadStopIsCategoryTwoAndLiftsWhenTheWayIsFree) {
  open_session();
  ASSERT_EQ(run_with_maps(40, free_).state, CycleState::kMoving);
  const CycleReport stopped = run_with_maps(40, blocked_ahead(grid_, robot_, free_));
  EXPECT_EQ(stopped.state, CycleState::kStopped);
  EXPECT_EQ(stopped.stop_category, StopCategory::kCategory2);
  EXPECT_TRUE(stopped.look_ahead.has_blocking_cell);
  EXPECT_EQ(stopped.look_ahead.critical_joint, 0);
  EXPECT_EQ(stopped.fault, CycleFault::kNone);
  EXPECT_TRUE(robot_.powered());
  EXPECT_EQ(run_with_maps(40, free_).state, CycleState::kMoving) << "no acknowledgement needed";
}

// The held map's speed limit (the protective separation's) caps the speed scale: the robot slows
// to it on a free map and keeps moving, stops at 0, and speeds up again with a map without one.
// A slow-down it decides names no joint or cell of the look-ahead.
TEST_F(SafetyCycleTest, TheMapsSpeedLimitCapsTheSpeedScale) {
  open_session();
  ASSERT_EQ(run_with_maps(40, free_).state, CycleState::kMoving);
  const double full_rad_s = robot_.read().velocity_rad_s[0];
  ASSERT_NEAR(full_rad_s, planned_[0], 1e-9);

  coprocessor_.set_speed_reduction_permille(750);
  const CycleReport slowed = run_with_maps(40, free_);
  EXPECT_EQ(slowed.state, CycleState::kSlowed);
  EXPECT_TRUE(slowed.separation_decides);
  EXPECT_DOUBLE_EQ(slowed.separation_limit, 0.25);
  EXPECT_DOUBLE_EQ(slowed.speed_scale, 0.25);
  EXPECT_NEAR(robot_.read().velocity_rad_s[0], 0.25 * full_rad_s, 1e-9);
  EXPECT_TRUE(robot_.moving());

  coprocessor_.set_speed_reduction_permille(1000);
  const CycleReport stopped = run_with_maps(40, free_);
  EXPECT_EQ(stopped.state, CycleState::kStopped);
  EXPECT_EQ(stopped.stop_category, StopCategory::kCategory2);
  EXPECT_EQ(stopped.fault, CycleFault::kNone);
  EXPECT_FALSE(robot_.moving());

  coprocessor_.set_speed_reduction_permille(0);
  const CycleReport again = run_with_maps(80, free_);
  EXPECT_EQ(again.state, CycleState::kMoving);
  EXPECT_FALSE(again.separation_decides);
  EXPECT_NEAR(robot_.read().velocity_rad_s[0], full_rad_s, 1e-9);
}

class SafetyCycleLookAheadOffTest : public SafetyCycleTest {
 protected:
  SafetyCycleLookAheadOffTest() : SafetyCycleTest(1, true) {}
};

// The closed-loop validation's negative control: with the look-ahead switched off the robot runs
// on into forbidden cells at full speed (what the validation must then catch), while faults still
// stop it.
TEST_F(SafetyCycleLookAheadOffTest, TheRobotRunsIntoForbiddenCellsButFaultsStillStopIt) {
  open_session();
  ASSERT_EQ(run_with_maps(40, free_).state, CycleState::kMoving);
  const CycleReport report = run_with_maps(40, blocked_ahead(grid_, robot_, free_));
  EXPECT_EQ(report.state, CycleState::kMoving);
  EXPECT_EQ(report.speed_scale, 1.0);
  EXPECT_EQ(report.look_ahead.reason, LookAheadReason::kSwitchedOff);
  EXPECT_TRUE(robot_.moving());
  send_map(free_, true);  // a whole update whose hash is wrong (a large delta: a few cycles' work)
  CycleReport fault = cycle();
  for (int i = 0; i < 10 && fault.state != CycleState::kFault; ++i) fault = cycle();
  EXPECT_EQ(fault.state, CycleState::kFault);
  EXPECT_EQ(fault.fault, CycleFault::kMapRefused);
}

}  // namespace
}  // namespace safecell
