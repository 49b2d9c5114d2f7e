#include "safecell/controller/host/simulated_robot.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

namespace safecell {
namespace {

double ramp(double current, double target, double accel, double decel, double dt) {
  // Slowing down (towards zero or across it) is limited by decel, speeding up by accel.
  const bool slowing = std::abs(target) < std::abs(current) || target * current < 0.0;
  const double limit = (slowing ? decel : accel) * dt;
  if (std::abs(target - current) <= limit) return target;
  return current + std::copysign(limit, target - current);
}

}  // namespace

SimulatedRobot::SimulatedRobot(const SimulatedRobotConfig& config) : config_(config) {
  if (config.joint_count == 0 || config.joint_count > kMaxJoints) {
    throw std::invalid_argument("simulated robot: joint count " +
                                std::to_string(config.joint_count) + " outside 1.." +
                                std::to_string(kMaxJoints));
  }
  for (std::uint32_t j = 0; j < config.joint_count; ++j) {
    const SimulatedJoint& joint = config.joints[j];
    const double values[] = {joint.max_speed_rad_s, joint.accel_rad_s2, joint.decel_rad_s2};
    for (const double value : values) {
      if (!std::isfinite(value) || value <= 0.0) {
        throw std::invalid_argument("simulated robot: joint " + std::to_string(j + 1) +
                                    ": speed, acceleration and deceleration limits must be "
                                    "finite and positive");
      }
    }
    if (!(joint.lo_rad < joint.hi_rad)) {
      throw std::invalid_argument("simulated robot: joint " + std::to_string(j + 1) +
                                  ": range is empty");
    }
    position_[j] = std::fmin(std::fmax(config.start_rad[j], joint.lo_rad), joint.hi_rad);
  }
  if (!std::isfinite(config.actuation_s) || config.actuation_s < 0.0) {
    throw std::invalid_argument("simulated robot: actuation delay must be finite and >= 0");
  }
}

RobotJoints SimulatedRobot::read() noexcept {
  RobotJoints joints;
  joints.joint_count = config_.joint_count;
  for (std::uint32_t j = 0; j < config_.joint_count; ++j) {
    joints.position_rad[j] = position_[j];
    joints.velocity_rad_s[j] = velocity_[j];
  }
  joints.read_time_ns = time_ns_;
  joints.powered = powered_;
  return joints;
}

void SimulatedRobot::queue(const Pending& command) noexcept {
  for (Pending& slot : pending_) {
    if (!slot.set) {
      slot = command;
      slot.set = true;
      slot.due_ns = time_ns_ + static_cast<std::uint64_t>(config_.actuation_s * 1e9);
      return;
    }
  }
  // A full queue (the caller commands faster than the drives take it): a stop still gets in,
  // in place of the oldest command, which is the safe side.
  if (command.stop) {
    pending_[0] = command;
    pending_[0].set = true;
    pending_[0].due_ns = time_ns_ + static_cast<std::uint64_t>(config_.actuation_s * 1e9);
  }
}

void SimulatedRobot::command_speed_scale(double scale) noexcept {
  Pending command;
  command.scale = std::isfinite(scale) ? std::fmin(std::fmax(scale, 0.0), 1.0) : 0.0;
  queue(command);
}

bool SimulatedRobot::command_joint_velocity(const double* velocity_rad_s,
                                            std::uint32_t joint_count) noexcept {
  Pending command;
  command.velocity = true;
  command.scale = 1.0;
  for (std::uint32_t j = 0; j < config_.joint_count && j < joint_count; ++j) {
    command.values[j] = std::isfinite(velocity_rad_s[j]) ? velocity_rad_s[j] : 0.0;
  }
  queue(command);
  return true;
}

void SimulatedRobot::stop(StopCategory category) noexcept {
  Pending command;
  command.stop = true;
  command.category = category;
  queue(command);
}

bool SimulatedRobot::restore_power() noexcept {
  if (moving()) return false;
  powered_ = true;
  // The stop is over: held at scale 0 until a command says otherwise (left stopping, the next
  // step at standstill would switch the drives off again before that command is due).
  stopping_ = false;
  target_scale_ = 0.0;
  return true;
}

void SimulatedRobot::apply_due() noexcept {
  // Commands in the order given, each once it is due.
  for (;;) {
    int oldest = -1;
    for (int i = 0; i < kQueue; ++i) {
      if (pending_[i].set && pending_[i].due_ns <= time_ns_ &&
          (oldest < 0 || pending_[i].due_ns < pending_[oldest].due_ns)) {
        oldest = i;
      }
    }
    if (oldest < 0) return;
    const Pending& command = pending_[oldest];
    if (command.stop) {
      stopping_ = true;
      stop_category_ = command.category;
      target_scale_ = 0.0;
    } else if (powered_) {
      stopping_ = false;
      target_scale_ = command.scale;
      if (command.velocity) {
        for (std::uint32_t j = 0; j < config_.joint_count; ++j) program_[j] = command.values[j];
      }
    }
    pending_[oldest].set = false;
  }
}

void SimulatedRobot::advance(double dt) noexcept {
  apply_due();
  scale_ = stopping_ ? 0.0 : target_scale_;
  bool still = true;
  for (std::uint32_t j = 0; j < config_.joint_count; ++j) {
    const SimulatedJoint& joint = config_.joints[j];
    double target = powered_ ? program_[j] * scale_ : 0.0;
    target = std::fmin(std::fmax(target, -joint.max_speed_rad_s), joint.max_speed_rad_s);
    const double before = velocity_[j];
    velocity_[j] = ramp(before, target, joint.accel_rad_s2, joint.decel_rad_s2, dt);
    position_[j] += 0.5 * (before + velocity_[j]) * dt;
    if (position_[j] <= joint.lo_rad || position_[j] >= joint.hi_rad) {
      position_[j] = std::fmin(std::fmax(position_[j], joint.lo_rad), joint.hi_rad);
      velocity_[j] = 0.0;
    }
    still = still && velocity_[j] == 0.0;
  }
  if (stopping_ && still && stop_category_ == StopCategory::kCategory1) powered_ = false;
  time_ns_ += static_cast<std::uint64_t>(std::llround(dt * 1e9));
}

void SimulatedRobot::step(double dt_s) noexcept {
  if (!std::isfinite(dt_s) || dt_s <= 0.0) return;
  const int steps = static_cast<int>(std::ceil(dt_s / 0.001));
  for (int s = 0; s < steps; ++s) advance(dt_s / steps);
}

bool SimulatedRobot::moving() const noexcept {
  for (std::uint32_t j = 0; j < config_.joint_count; ++j) {
    if (velocity_[j] != 0.0) return true;
  }
  return false;
}

StopModel SimulatedRobot::measure_stop_model(const SimulatedRobotConfig& config) {
  StopModel model;
  model.joint_count = config.joint_count;
  for (std::uint32_t j = 0; j < config.joint_count; ++j) {
    SimulatedRobotConfig one = config;
    for (std::uint32_t k = 0; k < config.joint_count; ++k) {
      one.joints[k].lo_rad = -1e9;  // no range limit in the way of the measurement
      one.joints[k].hi_rad = 1e9;
      one.start_rad[k] = 0.0;
    }
    SimulatedRobot robot(one);
    double velocity[kMaxJoints] = {};
    velocity[j] = config.joints[j].max_speed_rad_s;
    (void)robot.command_joint_velocity(velocity, config.joint_count);
    const double ramp_up = config.actuation_s + velocity[j] / config.joints[j].accel_rad_s2;
    robot.step(ramp_up + 0.01);
    const std::uint64_t stop_at = robot.time_ns();
    robot.stop(StopCategory::kCategory2);
    constexpr double kDt = 0.0005;
    for (int s = 0; s < 1'000'000 && robot.moving(); ++s) robot.advance(kDt);
    const double stop_time_s = static_cast<double>(robot.time_ns() - stop_at) * 1e-9;
    const double braking_s = stop_time_s - config.actuation_s;
    model.joints[j].latency_s = config.actuation_s + kDt;  // measured to within one step
    model.joints[j].decel_rad_s2 =
        braking_s > 0.0 ? velocity[j] / braking_s : config.joints[j].decel_rad_s2;
  }
  return model;
}

}  // namespace safecell
