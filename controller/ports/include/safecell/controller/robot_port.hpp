#pragma once
// The controller core's port to the robot: read the joints, command motion, stop.
//
// Shaped for the interfaces industrial robots offer a safety or motion add-on, cyclic at 125 to
// 500 Hz: a speed override (Universal Robots RTDE's speed slider, KUKA RSI's override, ABB EGM's
// speed reference) scales the robot's own program; joint velocities (RTDE speedj, RSI and EGM
// corrections) let the core drive a motion it planned itself (the safe gross-motion service).
// A backend implements what its robot has; a robot without joint velocity commands runs only
// under the override.
//
// Thread context (as ros2_control's hardware interfaces): every call comes from the controller's
// cycle task, once per cycle, in the order read -> command -> (stop); none may block for longer
// than the backend's documented bound, and none allocates.

#include <cstdint>

#include "safecell/cspace/grid_spec.hpp"

namespace safecell {

// IEC 60204-1 stop categories the core uses (category 0, removing power at once, is the robot's
// own emergency stop and not commanded from here).
enum class StopCategory : std::uint8_t {
  kCategory1 = 1,  // controlled stop, then power removed at standstill (faults)
  kCategory2 = 2,  // controlled stop, power kept (a slow-down that ends at zero)
};

struct RobotJoints {
  std::uint32_t joint_count = 0;
  double position_rad[kMaxJoints]{};
  double velocity_rad_s[kMaxJoints]{};
  std::uint64_t read_time_ns = 0;  // the controller's clock when the joints were sampled
  bool powered = true;             // false after a category 1 stop completed
  bool valid = true;               // false: the backend could not read the joints this cycle
};

class RobotPort {
 public:
  RobotPort() = default;
  RobotPort(const RobotPort&) = delete;
  RobotPort& operator=(const RobotPort&) = delete;

  virtual RobotJoints read() noexcept = 0;
  // Scales the robot's motion, 0..1 (the override). 0 holds the robot with power kept.
  virtual void command_speed_scale(double scale) noexcept = 0;
  // Joint velocities for the core's own motion (rad/s), already scaled; false when the robot
  // takes no velocity commands.
  virtual bool command_joint_velocity(const double* velocity_rad_s,
                                      std::uint32_t joint_count) noexcept = 0;
  // A controlled stop of the given category; repeated every cycle while the stop holds.
  virtual void stop(StopCategory category) noexcept = 0;
  // Power back after a category 1 stop (an operator's acknowledgement); false if refused.
  virtual bool restore_power() noexcept = 0;

 protected:
  ~RobotPort() = default;  // not deleted through the port (no operator delete on bare metal)
};

}  // namespace safecell
