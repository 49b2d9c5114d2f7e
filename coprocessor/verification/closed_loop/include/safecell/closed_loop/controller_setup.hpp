#pragma once
// The controller's side of a closed loop on one machine, from the coprocessor's cell: the
// safecell-controller configuration file (its grid to the last bit, so the session's grid
// fingerprints agree; the simulated robot's limits; the timing; the link's addresses; the task),
// and finding the program.

#include <cstdint>
#include <filesystem>
#include <stdexcept>
#include <string>
#include <vector>

#include "safecell/cell/cell_model.hpp"
#include "safecell/cspace/cspace_grid.hpp"
#include "safecell/errors/input_error.hpp"
#include "safecell/robot/robot_model.hpp"

namespace safecell {

// The closed loop cannot be set up on this machine (the controller program missing or not
// starting): the user's to mend, not a fault of the program.
class ClosedLoopSetupError : public InputError {
 public:
  using InputError::InputError;
};

struct SimulatedJointLimits {
  double max_speed_rad_s = 1.0;
  double accel_rad_s2 = 4.0;
  double decel_rad_s2 = 4.0;
};

struct ControllerSetup {
  std::vector<SimulatedJointLimits> joints;  // one per grid joint
  std::vector<double> start_rad;
  double actuation_ms = 2.0;
  double period_ms = 4.0;
  double max_period_ms = 12.0;  // a host without real-time scheduling jitters by milliseconds
  double budget_ms = 3.0;
  double watchdog_ms = 250.0;
  double max_data_age_ms = 250.0;
  double max_clock_lead_ms = 5.0;
  std::uint32_t min_healthy_cameras = 2;
  // The look-ahead's reach per joint; its worst case checks (cells + 1)^(joints - 1) lines of
  // cells, so this bounds the cycle's time.
  std::uint32_t max_look_ahead_cells = 12;
  std::string listen_address = "127.0.0.1";  // the controller's link address
  std::uint16_t listen_port = 0;
  std::string coprocessor_address = "127.0.0.1";
  std::uint16_t coprocessor_port = 0;
  std::uint64_t lut_fingerprint = 0;
  std::vector<std::vector<double>> goals_rad;
  bool repeat = true;
  // The moves as a robot program's (task.motion: program): planned without the map, the
  // look-ahead alone slows and stops them. Otherwise the safe gross-motion service.
  bool program_motion = false;
  // The closed-loop validation's negative control only: the controller does not slow or stop
  // the robot for people (safety.test_only_look_ahead_off).
  bool test_only_look_ahead_off = false;
};

// A configuration inside the grid: each joint clamped to 1 % of its range inside the range.
std::vector<double> inside_grid(const CspaceGrid& grid, std::vector<double> q);

// The simulated robot's limits for a cell's robot: the URDF's speed limits, held to a pace people
// near the robot find comfortable (1 rad/s for the arm's first three joints, 2 rad/s for the
// wrist), and the order of acceleration of a data sheet (4 and 8 rad/s^2).
std::vector<SimulatedJointLimits> comfortable_joint_limits(const RobotModel& robot,
                                                           const CspaceGrid& grid);

// The longest stop of the simulated robot from its top speed, in seconds: the actuation delay
// and the slowest joint's braking (its top speed over its deceleration).
[[nodiscard]] double stop_time_from_top_speed_s(const ControllerSetup& setup);

// The controller setup of a cell: the comfortable joint limits and the cell's camera threshold.
// Throws CellError naming the field when a stopping time in the cell file (entry_separation's,
// protective_separation's) is shorter than that robot's stop from its top speed: the separation
// distances would be too small for it.
[[nodiscard]] ControllerSetup controller_setup_of(const CellModel& cell, const CspaceGrid& grid);

// The YAML text of controller.example.yaml's shape. Numbers are written with 17 significant
// digits, so the controller reads back the very doubles (and the grid's fingerprint) given here.
std::string controller_config_yaml(const CspaceGrid& grid, const ControllerSetup& setup);

// The safecell-controller program: `explicit_path` when given; else $SAFECELL_CONTROLLER; else
// the one beside this executable; else the one this build made. Throws ClosedLoopSetupError
// naming every place looked at when none exists.
std::filesystem::path find_controller_program(const std::string& explicit_path);

// A UDP port on 127.0.0.1 free a moment ago (bound to port 0 and released).
std::uint16_t free_udp_port();

}  // namespace safecell
