#pragma once
// What a closed-loop run records, and the figures the report draws from it against the ground
// truth. The robot's truth is the controller's joint stream (the simulated robot it drives); the
// person's truth is the scenario. Contacts are found with FCL between the robot's collision
// shapes at every joint sample and the person's shapes at that moment: nothing here comes from the
// pipeline's own output.

#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "safecell/link/coprocessor_link.hpp"
#include "safecell/robot/robot_model.hpp"
#include "safecell/sim/human_figure.hpp"
#include "safecell/v1/joints.pb.h"

namespace safecell {

// One joint state of the controller, in seconds since the run began (coprocessor clock).
struct JointRecord {
  double time_s = 0.0;
  std::vector<double> q;
  std::vector<double> velocity;
  v1::ControllerState state = v1::CONTROLLER_STATE_UNSPECIFIED;
  double speed_scale = 0.0;
  std::uint32_t critical_joint = 0;  // from 1; 0: none
  std::uint64_t applied_map_version = 0;
  // When the controller swapped that map in, in the same seconds (0: not reported).
  double applied_map_time_s = 0.0;
};

// One map cycle of the coprocessor.
struct CycleRecord {
  double exposure_s = 0.0;
  double sent_s = 0.0;
  std::uint64_t map_version = 0;
  std::size_t forbidden_cells = 0;
  std::vector<std::size_t> blocked_per_camera;
  double features_ms = 0.0;
  double fusion_ms = 0.0;
  bool person_present = false;
  std::string all_forbidden;  // why the whole map was forbidden; empty: it was not
};

// A joint state from the link as a record, its times in seconds since start_ns (coprocessor
// clock, through the link's clock offset).
JointRecord joint_record(const ReceivedJointState& received, const ClockSync& clock,
                         std::uint64_t start_ns);

struct ClosedLoopRecord {
  std::vector<JointRecord> joints;
  std::vector<CycleRecord> cycles;
};

// The robot is moving when any joint is faster than this (rad/s).
inline constexpr double kMovingThreshold_rad_s = 0.01;

struct ContactFigures {
  std::size_t samples_checked = 0;  // joint samples with a person in the cell
  std::size_t contacts_while_moving = 0;
  std::size_t contacts_with_stopped_robot = 0;
  double min_human_distance_m = 0.0;  // infinity when nobody came in
  std::vector<double> distance_m;     // per joint sample; infinity without a person
};

// The person at a time (seconds since the run began), nullopt while nobody is in the cell.
using PersonAt = std::function<std::optional<HumanPose>(double time_s)>;

// FCL at every joint sample.
ContactFigures check_contacts(const RobotModel& robot_model, const ClosedLoopRecord& record,
                              const PersonAt& person_at);

struct TaskFigures {
  std::size_t moves_completed = 0;          // goal to goal
  std::size_t moves_with_person = 0;        // of those, overlapping the person's visit
  double move_time_s = 0.0;                 // mean over the moves with the person
  double move_time_without_people_s = 0.0;  // mean over the others
  bool completed_after_person_left = false;
};

// Goal arrivals from the joint samples (every joint within 0.02 rad of the goal the robot is
// heading for; it need not rest there): a move is the time from one arrival to the next goal's
// arrival, counted from the first arrival at the first goal.
TaskFigures task_figures(const ClosedLoopRecord& record,
                         const std::vector<std::vector<double>>& goals, double person_enters_s,
                         double person_leaves_s);

struct StateFigures {
  std::size_t stops = 0;      // entries into stopped
  std::size_t slowdowns = 0;  // entries into slowed
  std::size_t faults = 0;     // entries into fault
  // Exposure -> the controller swapped the map in (from the joint state's applied time; the first
  // joint state carrying the map when the controller does not report it), and when.
  std::vector<double> latency_ms;
  std::vector<double> latency_at_s;
};

StateFigures state_figures(const ClosedLoopRecord& record);

const char* state_name(v1::ControllerState state);
// The state state_name() names `name`; nullopt for "unknown" or another word.
std::optional<v1::ControllerState> state_named(const std::string& name);

}  // namespace safecell
