#pragma once
// The configuration of the Linux controller module (safecell-controller), one YAML file:
//
//   grid       m_max_m and the joints (lo_rad, hi_rad, l_m, discretised): the same grid the
//              coprocessor's cell gives, to the last bit (its fingerprint opens the session)
//   robot      the simulated robot: per joint max_speed_rad_s, accel_rad_s2, decel_rad_s2; the
//              actuation delay; the start joints
//   timing     period_ms, max_period_ms, budget_ms, watchdog_ms (T_wd), max_data_age_ms,
//   max_clock_lead_ms safety     human_speed_m_s, min_healthy_cameras, max_look_ahead_cells, the
//   stop categories link       listen and coprocessor addresses (IPv4:port), ids, the LUT
//   fingerprint task       goals_rad (a list of joint vectors), repeat
// controller/host/controller.example.yaml has every field with its meaning. Every refusal names
// the file, line, field and value, and what was expected (ControllerConfigError).

#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

#include "safecell/controller/controller_link.hpp"
#include "safecell/controller/host/simulated_robot.hpp"
#include "safecell/controller/host/udp_link_port.hpp"
#include "safecell/controller/robot_port.hpp"
#include "safecell/cspace/grid_spec.hpp"

namespace safecell {

class ControllerConfigError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

struct ControllerTiming {
  double period_ms = 4.0;
  // The watchdog's window: a cycle that begins later than this after the last is a fault (stop).
  // The look-ahead takes it as t_cycle, the longest time to its next check. The file's default:
  // 1.5 periods. A
  // host without real-time scheduling needs more than the default (its cycles jitter by
  // milliseconds under load), and pays for it with a longer look-ahead.
  double max_period_ms = 6.0;
  double budget_ms = 2.0;
  double watchdog_ms = 100.0;
  double max_data_age_ms = 150.0;
  double max_clock_lead_ms = 5.0;
};

struct ControllerSafety {
  double human_speed_m_s = 1.6;
  std::uint32_t min_healthy_cameras = 1;
  std::uint32_t max_look_ahead_cells = 24;
  StopCategory look_ahead_stop = StopCategory::kCategory2;
  StopCategory fault_stop = StopCategory::kCategory1;
  // safety.test_only_look_ahead_off: the closed-loop validation's negative control (the robot
  // is not slowed or stopped for people). Never in a product file; the program warns loudly.
  bool test_only_look_ahead_off = false;
};

struct ControllerLinkSettings {
  UdpAddress listen{"127.0.0.1", 47701};
  UdpAddress coprocessor{"127.0.0.1", 47700};
  std::uint32_t controller_id = 2;
  std::uint32_t coprocessor_id = 1;
  std::uint64_t lut_fingerprint = 0;
  // MapStore work units per link slice (ControllerLinkConfig::map_work_per_poll): a cycle does
  // one slice, the idle time between cycles more.
  std::uint32_t map_work_per_slice = ControllerLinkConfig{}.map_work_per_poll;
};

// How the task's moves are made. Both run under the safety cycle's look-ahead.
enum class TaskMotion : std::uint8_t {
  kGrossMotion,  // the safe gross-motion service: paths of free cells, re-planned around people
  kProgram,      // as a robot program's moves: planned once without the map (an empty one), so
                 // that the look-ahead alone slows and stops them for people
};

struct ControllerTask {
  std::vector<std::vector<double>> goals_rad;
  bool repeat = false;
  TaskMotion motion = TaskMotion::kGrossMotion;
};

struct ControllerConfig {
  std::string source;  // the file it came from
  GridSpec grid;
  SimulatedRobotConfig robot;
  ControllerTiming timing;
  ControllerSafety safety;
  ControllerLinkSettings link;
  ControllerTask task;
  std::uint32_t pool_blocks = 0;  // 0: the map held dense; N: compressed, a pool of N blocks
};

// Reads and checks a configuration file; throws ControllerConfigError.
ControllerConfig load_controller_config(const std::string& path);
// The same from text (`source` names it in errors).
ControllerConfig parse_controller_config(const std::string& text, const std::string& source);

}  // namespace safecell
