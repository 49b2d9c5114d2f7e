// The figures of a closed-loop run, from synthetic records whose answers are known: moves between
// goals (the robot does not rest at a goal: the service turns at once), state changes, latency
// from the controller's own applied time, and contacts against FCL with the real robot model.

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <numbers>

#include "safecell/cell/cell_file.hpp"
#include "safecell/cell/cell_model.hpp"
#include "safecell/closed_loop/closed_loop_record.hpp"

namespace safecell {
namespace {

// Joint 1 goes between -1 and +1 rad at a constant 1 rad/s, turning at once at each end (as the
// gross-motion service does: it heads for the next goal on arrival), so it never rests.
ClosedLoopRecord swinging(double seconds) {
  ClosedLoopRecord record;
  for (int step = 0; step * 0.004 <= seconds; ++step) {
    const double t = step * 0.004;
    const double phase = std::fmod(t, 4.0);  // 0..2 s up, 2..4 s down
    JointRecord sample;
    sample.time_s = t;
    sample.q = {phase < 2.0 ? -1.0 + phase : 3.0 - phase, 0.0};
    sample.velocity = {phase < 2.0 ? 1.0 : -1.0, 0.0};
    sample.state = v1::CONTROLLER_STATE_MOVING;
    record.joints.push_back(sample);
  }
  return record;
}

TEST(TaskFigures, MovesAreCountedWithoutRestAtTheGoals) {
  const ClosedLoopRecord record = swinging(20.0);
  const std::vector<std::vector<double>> goals{{1.0, 0.0}, {-1.0, 0.0}};
  const TaskFigures task = task_figures(record, goals, 8.0, 11.0);
  // First arrival at +1 rad at 2 s; moves end at 4, 6, ..., 20 s (9 moves; within the 0.02 rad
  // tolerance a little before each).
  EXPECT_EQ(task.moves_completed, 9U);
  EXPECT_NEAR(task.move_time_without_people_s, 2.0, 0.05);
  EXPECT_GE(task.moves_with_person, 2U);  // the moves overlapping 8..11 s
  EXPECT_TRUE(task.completed_after_person_left);
  EXPECT_FALSE(task_figures(record, goals, 8.0, 19.0).completed_after_person_left);
}

TEST(StateFigures, EntriesAndTheControllersOwnAppliedTime) {
  ClosedLoopRecord record;
  const v1::ControllerState states[] = {v1::CONTROLLER_STATE_MOVING,  v1::CONTROLLER_STATE_SLOWED,
                                        v1::CONTROLLER_STATE_STOPPED, v1::CONTROLLER_STATE_STOPPED,
                                        v1::CONTROLLER_STATE_MOVING,  v1::CONTROLLER_STATE_FAULT};
  for (std::size_t i = 0; i < std::size(states); ++i) {
    JointRecord sample;
    sample.time_s = 0.1 * static_cast<double>(i + 1);
    sample.state = states[i];
    sample.applied_map_version = i < 3 ? 1 : 2;
    sample.applied_map_time_s = i < 3 ? 0.05 : 0.33;
    record.joints.push_back(sample);
  }
  for (const auto& [exposure_s, version] : {std::pair{0.04, 1}, std::pair{0.30, 2}}) {
    CycleRecord cycle;
    cycle.exposure_s = exposure_s;
    cycle.map_version = static_cast<std::uint64_t>(version);
    record.cycles.push_back(cycle);
  }
  const StateFigures figures = state_figures(record);
  EXPECT_EQ(figures.slowdowns, 1U);
  EXPECT_EQ(figures.stops, 1U);
  EXPECT_EQ(figures.faults, 1U);
  ASSERT_EQ(figures.latency_ms.size(), 2U);
  EXPECT_NEAR(figures.latency_ms[0], 10.0, 1e-9);  // 0.05 - 0.04 s: the applied time, not 0.1 s
  EXPECT_NEAR(figures.latency_ms[1], 30.0, 1e-9);
}

TEST(ContactFigures, ARobotMovingIntoThePersonIsAContactWhileMoving) {
  const CellModel cell = load_cell_model(load_cell_file_or_default(""));
  ClosedLoopRecord record;
  JointRecord far;
  far.time_s = 0.0;
  far.q = {std::numbers::pi / 2, 0.5, 0.9, 0.0, 0.6, 0.0};  // the arm points along +y
  far.velocity = {0.5, 0.0, 0.0, 0.0, 0.0, 0.0};
  JointRecord into = far;
  into.time_s = 1.0;
  into.q[0] = 0.0;  // the arm points along +x, where the person stands
  JointRecord still = into;
  still.time_s = 2.0;
  still.velocity = {0.0, 0.0, 0.0, 0.0, 0.0, 0.0};
  record.joints = {far, into, still};
  const PersonAt person_at = [](double) {
    HumanPose pose;
    pose.position_m = {1.1, 0.0};
    return std::optional<HumanPose>(pose);
  };
  const ContactFigures contacts = check_contacts(*cell.robot, record, person_at);
  EXPECT_EQ(contacts.samples_checked, 3U);
  EXPECT_EQ(contacts.contacts_while_moving, 1U);
  EXPECT_EQ(contacts.contacts_with_stopped_robot, 1U);
  EXPECT_GT(contacts.distance_m[0], 0.3);
  EXPECT_EQ(contacts.min_human_distance_m, 0.0);
  // Nobody in the cell: nothing checked, the distance infinite.
  const ContactFigures empty =
      check_contacts(*cell.robot, record, [](double) { return std::optional<HumanPose>(); });
  EXPECT_EQ(empty.samples_checked, 0U);
  EXPECT_EQ(empty.min_human_distance_m, std::numeric_limits<double>::infinity());
}

}  // namespace
}  // namespace safecell
