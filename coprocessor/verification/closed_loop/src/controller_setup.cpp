#include "safecell/closed_loop/controller_setup.hpp"

#include <algorithm>
#include <boost/asio/io_context.hpp>
#include <boost/asio/ip/udp.hpp>
#include <cstdlib>
#include <iomanip>
#include <sstream>
#include <stdexcept>
#include <system_error>

#include "safecell/cell/cell_error.hpp"

namespace safecell {
namespace {

std::string exact(double value) {
  std::ostringstream text;
  text << std::setprecision(17) << value;
  return text.str();
}

std::string list(const std::vector<double>& values) {
  std::string text = "[";
  for (std::size_t i = 0; i < values.size(); ++i) text += (i ? ", " : "") + exact(values[i]);
  return text + "]";
}

}  // namespace

std::vector<SimulatedJointLimits> comfortable_joint_limits(const RobotModel& robot,
                                                           const CspaceGrid& grid) {
  std::vector<SimulatedJointLimits> limits;
  for (std::uint32_t j = 0; j < grid.joint_count(); ++j) {
    const bool arm = j < 3;
    const double urdf = j < robot.joints.size() ? robot.joints[j].max_speed : 0.0;
    const double pace = arm ? 1.0 : 2.0;
    const double accel = arm ? 4.0 : 8.0;
    limits.push_back({urdf > 0.0 ? std::min(urdf, pace) : pace, accel, accel});
  }
  return limits;
}

double stop_time_from_top_speed_s(const ControllerSetup& setup) {
  double braking_s = 0.0;
  for (const SimulatedJointLimits& joint : setup.joints) {
    braking_s = std::max(braking_s, joint.max_speed_rad_s / joint.decel_rad_s2);
  }
  return setup.actuation_ms * 1e-3 + braking_s;
}

namespace {

// The cell's stopping time for a separation distance must cover the robot's stop.
void require_stop_within(const SeparationDistanceConfig& separation, const std::string& field,
                         const CellConfig& cell, double stop_s) {
  if (separation.stopping_s >= stop_s) return;
  SourceLine where = separation.at;
  const bool defaulted = where.source.empty();
  if (defaulted) where.source = cell.source;
  std::ostringstream problem;
  problem << "value " << separation.stopping_s << " s" << (defaulted ? " (the default)" : "")
          << ", expected at least " << stop_s << " s: the simulated robot stops from its top "
          << "speed in that long, so the separation distance would be too small";
  throw_cell_error(where, field + ".stopping_s", problem.str());
}

}  // namespace

ControllerSetup controller_setup_of(const CellModel& cell, const CspaceGrid& grid) {
  if (!cell.robot) throw std::invalid_argument("controller setup: the cell has no robot model");
  ControllerSetup setup;
  setup.joints = comfortable_joint_limits(*cell.robot, grid);
  setup.min_healthy_cameras = static_cast<std::uint32_t>(cell.camera_threshold);
  const double stop_s = stop_time_from_top_speed_s(setup);
  require_stop_within(cell.config.entry_separation, "entry_separation", cell.config, stop_s);
  if (cell.config.protective_separation) {
    require_stop_within(*cell.config.protective_separation, "protective_separation", cell.config,
                        stop_s);
  }
  return setup;
}

std::vector<double> inside_grid(const CspaceGrid& grid, std::vector<double> q) {
  q.resize(grid.joint_count(), 0.0);
  for (std::uint32_t j = 0; j < grid.joint_count(); ++j) {
    const JointSpec& joint = grid.joint(j);
    const double margin = 0.01 * (joint.hi_rad - joint.lo_rad);
    q[j] = std::clamp(q[j], joint.lo_rad + margin, joint.hi_rad - margin);
  }
  return q;
}

std::string controller_config_yaml(const CspaceGrid& grid, const ControllerSetup& setup) {
  if (setup.joints.size() != grid.joint_count() || setup.start_rad.size() != grid.joint_count()) {
    throw std::invalid_argument("controller setup: " + std::to_string(setup.joints.size()) +
                                " joint limits and " + std::to_string(setup.start_rad.size()) +
                                " start values for a grid of " +
                                std::to_string(grid.joint_count()) + " joints");
  }
  std::ostringstream yaml;
  yaml << "# Written by safecell for its cell; the grid is the coprocessor's to the last bit.\n"
       << "grid:\n  m_max_m: " << exact(grid.m_max_m()) << "\n  joints:\n";
  for (std::uint32_t j = 0; j < grid.joint_count(); ++j) {
    const JointSpec& joint = grid.joint(j);
    yaml << "    - {lo_rad: " << exact(joint.lo_rad) << ", hi_rad: " << exact(joint.hi_rad)
         << ", l_m: " << exact(joint.l_m)
         << ", discretised: " << (joint.discretised ? "true" : "false") << "}\n";
  }
  yaml << "robot:\n  actuation_ms: " << exact(setup.actuation_ms) << "\n  joints:\n";
  for (const SimulatedJointLimits& limits : setup.joints) {
    yaml << "    - {max_speed_rad_s: " << exact(limits.max_speed_rad_s)
         << ", accel_rad_s2: " << exact(limits.accel_rad_s2)
         << ", decel_rad_s2: " << exact(limits.decel_rad_s2) << "}\n";
  }
  yaml << "  start_rad: " << list(setup.start_rad) << "\n"
       << "timing:\n  period_ms: " << exact(setup.period_ms)
       << "\n  max_period_ms: " << exact(setup.max_period_ms)
       << "\n  budget_ms: " << exact(setup.budget_ms)
       << "\n  watchdog_ms: " << exact(setup.watchdog_ms)
       << "\n  max_data_age_ms: " << exact(setup.max_data_age_ms)
       << "\n  max_clock_lead_ms: " << exact(setup.max_clock_lead_ms) << "\n"
       << "safety:\n  min_healthy_cameras: " << setup.min_healthy_cameras
       << "\n  max_look_ahead_cells: " << setup.max_look_ahead_cells << "\n"
       << (setup.test_only_look_ahead_off ? "  test_only_look_ahead_off: true\n" : "")
       << "link:\n  listen: " << setup.listen_address << ':' << setup.listen_port
       << "\n  coprocessor: " << setup.coprocessor_address << ':' << setup.coprocessor_port
       << "\n  lut_fingerprint: " << setup.lut_fingerprint << "\n"
       << "task:\n  goals_rad:" << (setup.goals_rad.empty() ? " []\n" : "\n");
  for (const std::vector<double>& goal : setup.goals_rad) yaml << "    - " << list(goal) << "\n";
  yaml << "  repeat: " << (setup.repeat ? "true" : "false") << "\n";
  yaml << "  motion: " << (setup.program_motion ? "program" : "gross_motion") << "\n";
  return yaml.str();
}

std::filesystem::path find_controller_program(const std::string& explicit_path) {
  namespace fs = std::filesystem;
  std::vector<fs::path> places;
  if (!explicit_path.empty()) {
    places.emplace_back(explicit_path);
  } else {
    if (const char* from_env = std::getenv("SAFECELL_CONTROLLER")) places.emplace_back(from_env);
    std::error_code error;
    const fs::path self = fs::read_symlink("/proc/self/exe", error);
    if (!error) places.push_back(self.parent_path() / "safecell-controller");
#ifdef SAFECELL_CONTROLLER_BUILD_PATH
    places.emplace_back(SAFECELL_CONTROLLER_BUILD_PATH);
#endif
  }
  std::string looked;
  for (const fs::path& place : places) {
    std::error_code error;
    if (fs::is_regular_file(place, error)) return place;
    looked += (looked.empty() ? "" : ", ") + place.string();
  }
  throw ClosedLoopSetupError(
      "the controller program safecell-controller was not found (looked at " +
      (looked.empty() ? std::string("nothing") : looked) +
      "); build it (cmake --build --preset host) or name it with "
      "--controller-program");
}

std::uint16_t free_udp_port() {
  boost::asio::io_context context;
  boost::asio::ip::udp::socket socket(
      context, boost::asio::ip::udp::endpoint(boost::asio::ip::make_address("127.0.0.1"), 0));
  return socket.local_endpoint().port();
}

}  // namespace safecell
