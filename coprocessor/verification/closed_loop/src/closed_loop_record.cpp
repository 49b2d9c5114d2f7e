#include "safecell/closed_loop/closed_loop_record.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>

#include "safecell/robot/kinematics.hpp"
#include "safecell/sim/ground_truth.hpp"

namespace safecell {
namespace {

constexpr double kGoalTolerance_rad = 0.02;

double fastest_joint(const std::vector<double>& velocity) {
  double fastest = 0.0;
  for (const double v : velocity) fastest = std::max(fastest, std::abs(v));
  return fastest;
}

bool at(const std::vector<double>& q, const std::vector<double>& goal) {
  if (q.size() != goal.size()) return false;
  for (std::size_t j = 0; j < q.size(); ++j) {
    if (std::abs(q[j] - goal[j]) > kGoalTolerance_rad) return false;
  }
  return true;
}

double mean(const std::vector<double>& values) {
  if (values.empty()) return 0.0;
  double sum = 0.0;
  for (const double v : values) sum += v;
  return sum / static_cast<double>(values.size());
}

}  // namespace

JointRecord joint_record(const ReceivedJointState& received, const ClockSync& clock,
                         std::uint64_t start_ns) {
  const auto since_start = [start_ns](std::uint64_t ns) {
    return (static_cast<double>(ns) - static_cast<double>(start_ns)) * 1e-9;
  };
  const v1::JointState& state = received.state;
  JointRecord sample;
  sample.time_s = since_start(received.coprocessor_time_ns);
  sample.q.assign(state.position_rad().begin(), state.position_rad().end());
  sample.velocity.assign(state.velocity_rad_s().begin(), state.velocity_rad_s().end());
  sample.state = state.state();
  sample.speed_scale = state.speed_scale();
  sample.critical_joint = state.critical_joint();
  sample.applied_map_version = state.applied_map_version();
  if (state.applied_map_time_ns() != 0 && clock.offset()) {
    sample.applied_map_time_s = since_start(clock.to_coprocessor(state.applied_map_time_ns()));
  }
  return sample;
}

ContactFigures check_contacts(const RobotModel& robot_model, const ClosedLoopRecord& record,
                              const PersonAt& person_at) {
  ContactFigures figures;
  figures.min_human_distance_m = std::numeric_limits<double>::infinity();
  figures.distance_m.assign(record.joints.size(), std::numeric_limits<double>::infinity());
  for (std::size_t i = 0; i < record.joints.size(); ++i) {
    const JointRecord& sample = record.joints[i];
    const std::optional<HumanPose> person = person_at(sample.time_s);
    if (!person || sample.q.size() != robot_model.joints.size()) continue;
    ++figures.samples_checked;
    const GroundTruth truth(human_shapes(*person));
    const std::vector<PlacedShape> robot = collision_shapes_at(robot_model, sample.q);
    const double distance = truth.min_distance_m(robot);
    figures.distance_m[i] = distance;
    figures.min_human_distance_m = std::min(figures.min_human_distance_m, distance);
    if (distance > 0.0 && !truth.collides(robot)) continue;
    if (fastest_joint(sample.velocity) > kMovingThreshold_rad_s) {
      ++figures.contacts_while_moving;
    } else {
      ++figures.contacts_with_stopped_robot;
    }
  }
  return figures;
}

TaskFigures task_figures(const ClosedLoopRecord& record,
                         const std::vector<std::vector<double>>& goals, double person_enters_s,
                         double person_leaves_s) {
  TaskFigures figures;
  if (goals.empty()) return figures;
  // The arrivals in order: the first time the robot rests at the goal it is heading for.
  std::vector<double> arrivals;
  std::size_t next_goal = 0;
  bool started = false;  // the first arrival at goal 0 starts the clock
  for (const JointRecord& sample : record.joints) {
    // Arrived when every joint is within the tolerance of the goal: the gross-motion service
    // turns to the next goal at once, so the robot need not come to rest there.
    if (!at(sample.q, goals[next_goal])) continue;
    if (started || next_goal == 0) {
      arrivals.push_back(sample.time_s);
      started = true;
    }
    next_goal = (next_goal + 1) % goals.size();
  }
  std::vector<double> with_person;
  std::vector<double> without;
  for (std::size_t i = 1; i < arrivals.size(); ++i) {
    const double begin = arrivals[i - 1];
    const double end = arrivals[i];
    ++figures.moves_completed;
    const bool overlaps = begin < person_leaves_s && end > person_enters_s;
    (overlaps ? with_person : without).push_back(end - begin);
    if (begin >= person_leaves_s) figures.completed_after_person_left = true;
  }
  figures.moves_with_person = with_person.size();
  figures.move_time_s = mean(with_person);
  figures.move_time_without_people_s = mean(without);
  return figures;
}

StateFigures state_figures(const ClosedLoopRecord& record) {
  StateFigures figures;
  v1::ControllerState last = v1::CONTROLLER_STATE_UNSPECIFIED;
  for (const JointRecord& sample : record.joints) {
    if (sample.state != last) {
      if (sample.state == v1::CONTROLLER_STATE_STOPPED) ++figures.stops;
      if (sample.state == v1::CONTROLLER_STATE_SLOWED) ++figures.slowdowns;
      if (sample.state == v1::CONTROLLER_STATE_FAULT) ++figures.faults;
      last = sample.state;
    }
  }
  std::map<std::uint64_t, double> exposure_of;
  for (const CycleRecord& cycle : record.cycles) exposure_of[cycle.map_version] = cycle.exposure_s;
  std::uint64_t held = 0;
  for (const JointRecord& sample : record.joints) {
    if (sample.applied_map_version == held) continue;
    held = sample.applied_map_version;
    const auto exposure = exposure_of.find(held);
    if (exposure != exposure_of.end()) {
      const double applied_s =
          sample.applied_map_time_s > 0.0 ? sample.applied_map_time_s : sample.time_s;
      figures.latency_ms.push_back((applied_s - exposure->second) * 1e3);
      figures.latency_at_s.push_back(applied_s);
    }
  }
  return figures;
}

const char* state_name(v1::ControllerState state) {
  switch (state) {
    case v1::CONTROLLER_STATE_WAITING:
      return "waiting";
    case v1::CONTROLLER_STATE_MOVING:
      return "moving";
    case v1::CONTROLLER_STATE_SLOWED:
      return "slowed";
    case v1::CONTROLLER_STATE_STOPPED:
      return "stopped";
    case v1::CONTROLLER_STATE_FAULT:
      return "fault";
    default:
      return "unknown";
  }
}

std::optional<v1::ControllerState> state_named(const std::string& name) {
  for (int value = v1::ControllerState_MIN; value <= v1::ControllerState_MAX; ++value) {
    if (v1::ControllerState_IsValid(value) &&
        name == state_name(static_cast<v1::ControllerState>(value))) {
      return static_cast<v1::ControllerState>(value);
    }
  }
  return std::nullopt;
}

}  // namespace safecell
