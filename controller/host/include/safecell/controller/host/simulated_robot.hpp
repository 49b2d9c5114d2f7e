#pragma once
// A simulated robot behind the core's RobotPort, for the Linux module, the demo and the tests:
// joints that follow velocity commands within their speed, acceleration and deceleration limits
// (the robot model's or the cell file's), with a delay from a command to the drives acting on it.
//
//   joint velocities  command_joint_velocity(): each joint ramps to its target (accelerating at
//                     most accel, slowing at most decel), clamped to max speed
//   override          command_speed_scale(): the last velocity command (the robot's "program")
//                     scaled; the scale itself ramps no faster than the joints may
//   stops             category 2: every joint decelerates at its limit, power kept; category 1:
//                     the same, then power off at standstill until restore_power()
// Joints stop dead at their range limits. Time advances only in step(dt).
// The stopping behaviour the core plans with comes from this simulation, measured
// (measure_stop_model), not assumed.
// Thread context: one thread (the host module's cycle or a test). No allocation after
// construction.

#include <cstdint>

#include "safecell/controller/clock_port.hpp"
#include "safecell/controller/robot_port.hpp"
#include "safecell/controller/stop_model.hpp"

namespace safecell {

struct SimulatedJoint {
  double lo_rad = -3.14;
  double hi_rad = 3.14;
  double max_speed_rad_s = 1.0;
  double accel_rad_s2 = 4.0;
  double decel_rad_s2 = 4.0;
};

struct SimulatedRobotConfig {
  std::uint32_t joint_count = 0;
  SimulatedJoint joints[kMaxJoints]{};
  double start_rad[kMaxJoints]{};
  double actuation_s = 0.002;  // from a command to the drives acting on it
};

class SimulatedRobot final : public RobotPort {
 public:
  // Throws std::invalid_argument for a joint count outside 1..kMaxJoints or limits that are not
  // finite and positive (hosted code: this runs at init).
  explicit SimulatedRobot(const SimulatedRobotConfig& config);

  RobotJoints read() noexcept override;
  void command_speed_scale(double scale) noexcept override;
  bool command_joint_velocity(const double* velocity_rad_s,
                              std::uint32_t joint_count) noexcept override;
  void stop(StopCategory category) noexcept override;
  bool restore_power() noexcept override;

  // Advances the simulation by dt_s seconds (sub-stepped at 1 ms at most).
  void step(double dt_s) noexcept;
  std::uint64_t time_ns() const noexcept { return time_ns_; }
  void set_time_ns(std::uint64_t time_ns) noexcept { time_ns_ = time_ns; }

  bool moving() const noexcept;
  bool powered() const noexcept { return powered_; }
  double speed_scale() const noexcept { return scale_; }
  const SimulatedRobotConfig& config() const noexcept { return config_; }

  // Stops joint by joint from full speed in a fresh simulation and measures each one's time to
  // standstill and distance: the core's StopModel (latency = actuation, deceleration from the
  // measured time).
  static StopModel measure_stop_model(const SimulatedRobotConfig& config);

 private:
  // A command waits actuation_s before the drives act on it.
  struct Pending {
    bool set = false;
    std::uint64_t due_ns = 0;
    bool stop = false;
    StopCategory category = StopCategory::kCategory2;
    bool velocity = false;  // a joint velocity command, else a speed scale
    double values[kMaxJoints]{};
    double scale = 0.0;
  };
  void queue(const Pending& command) noexcept;
  void apply_due() noexcept;
  void advance(double dt_s) noexcept;

  SimulatedRobotConfig config_;
  std::uint64_t time_ns_ = 0;
  double position_[kMaxJoints]{};
  double velocity_[kMaxJoints]{};
  double program_[kMaxJoints]{};  // the velocity command before the override
  double scale_ = 0.0;            // the override in force
  double target_scale_ = 0.0;
  bool stopping_ = true;  // starts held: no motion before the core allows it
  StopCategory stop_category_ = StopCategory::kCategory2;
  bool powered_ = true;
  static constexpr int kQueue = 8;
  Pending pending_[kQueue]{};
};

// The simulation's own time as the core's clock, for runs faster or slower than real time (the
// tests, the closed loop in simulation).
class SimulatedClock final : public ClockPort {
 public:
  explicit SimulatedClock(const SimulatedRobot& robot) noexcept : robot_(robot) {}
  std::uint64_t now_ns() noexcept override { return robot_.time_ns(); }

 private:
  const SimulatedRobot& robot_;
};

}  // namespace safecell
