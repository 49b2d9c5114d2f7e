#include "safecell/closed_loop/controller_session.hpp"

#include <chrono>
#include <cmath>
#include <fstream>

#include "safecell/files/atomic_write.hpp"
#include "safecell/link/link_errors.hpp"
#include "safecell/silhouettes/configuration_silhouettes.hpp"

namespace safecell {
namespace {

constexpr std::chrono::seconds kStartUp{10};
constexpr std::size_t kTailLines = 5;

std::uint32_t microseconds(double ms) { return static_cast<std::uint32_t>(std::lround(ms * 1e3)); }

}  // namespace

ControllerSession::ControllerSession(const CellModel& cell, const CspaceGrid& grid,
                                     SensingPipeline& pipeline, std::uint64_t lut_fingerprint,
                                     ControllerSetup setup,
                                     const ControllerSessionSettings& settings, std::ostream& log)
    : pipeline_(pipeline),
      cell_(cell),
      grid_(grid),
      log_(log),
      settings_(settings),
      config_file_(settings.folder / "controller.yaml"),
      setup_(std::move(setup)),
      log_file_(settings.folder / "controller.log"),
      transport_({"127.0.0.1", 0}, {"127.0.0.1", 0}) {
  // This end binds first, so that the controller's file can name our port.
  setup_.coprocessor_port = transport_.local_port();
  setup_.listen_port = free_udp_port();
  setup_.lut_fingerprint = lut_fingerprint;
  LinkRoute route{setup_.listen_port, setup_.coprocessor_port};
  if (settings.route) route = settings.route(setup_.coprocessor_port, setup_.listen_port);
  transport_.set_peer({"127.0.0.1", route.coprocessor_sends_to});
  ControllerSetup written = setup_;
  written.coprocessor_port = route.controller_sends_to;
  written.lut_fingerprint = settings.controller_lut_fingerprint.value_or(lut_fingerprint);
  write_file_atomically(config_file_, controller_config_yaml(grid, written));
  start_program(settings.extra_args);
  log << "controller: " << settings.program.string() << " (log " << log_file_.string() << ")\n";
  if (settings.on_started) settings.on_started(*process_);

  link_config_.cell_count = grid.cell_count();
  link_config_.grid_fingerprint = grid.fingerprint();
  link_config_.lut_fingerprint = lut_fingerprint;
  link_config_.map_cycle_us = static_cast<std::uint32_t>(std::lround(1e6 / settings.fps));
  link_config_.control_cycle_us = microseconds(setup_.period_ms);
  link_config_.watchdog_us = microseconds(setup_.watchdog_ms);
  link_config_.max_data_age_us = microseconds(setup_.max_data_age_ms);
  for (const SimulatedJointLimits& joint : setup_.joints) {
    service_settings_.joints.max_acceleration_rad_s2.push_back(
        std::max(joint.accel_rad_s2, joint.decel_rad_s2));
  }
  service_settings_.widening_budget_m =
      removal_widening_m(*cell.robot, grid, 0.0, settings.sync_error_s).value_or(0.02);
  service_settings_.camera_threshold = static_cast<std::uint32_t>(cell.camera_threshold);
  service_settings_.maps_of_stopped_cycles = settings.maps_of_stopped_cycles;
  open_link();
}

void ControllerSession::start_program(const std::vector<std::string>& extra_args) {
  std::vector<std::string> args{"--config", config_file_.string(), "--status-hz", "1"};
  args.insert(args.end(), extra_args.begin(), extra_args.end());
  process_ =
      std::make_unique<ControllerProcess>(settings_.program, args, log_file_, settings_.channel);
}

void ControllerSession::open_link() {
  service_.reset();
  link_ = std::make_unique<CoprocessorLink>(link_config_, transport_, 0, settings_.clock);
  // The program needs a moment to start; a refusal, or the program gone, ends the wait.
  const auto give_up = std::chrono::steady_clock::now() + kStartUp;
  while (true) {
    try {
      link_->open(std::chrono::milliseconds(500));
      break;
    } catch (const LinkSetupError& error) {
      if (link_->refused_because() || !process_->running() ||
          std::chrono::steady_clock::now() > give_up) {
        throw LinkSetupError(std::string(error.what()) +
                             "; the controller's last words:" + log_tail());
      }
    }
  }
  service_ = std::make_unique<SensingService>(
      grid_, pipeline_, *link_, service_settings_,
      camera_views_for(cell_, settings_.camera_references,
                       [this](std::string_view line) { log_ << "cameras: " << line << "\n"; }));
}

void ControllerSession::restart_controller(const std::vector<std::string>& extra_args) {
  process_->kill();
  ++restarts_;
  log_file_ = settings_.folder / ("controller." + std::to_string(restarts_) + ".log");
  start_program(extra_args);
}

void ControllerSession::reopen_link() { open_link(); }

ControllerSession::~ControllerSession() = default;

ControllerSessionSettings real_time_session(const std::filesystem::path& program,
                                            const std::filesystem::path& folder, double fps,
                                            double sync_error_s,
                                            std::vector<cv::Mat> camera_references) {
  ControllerSessionSettings settings;
  settings.camera_references = std::move(camera_references);
  settings.program = program;
  settings.folder = folder;
  settings.fps = fps;
  settings.sync_error_s = sync_error_s;
  return settings;
}

std::string controller_log_tail(const std::filesystem::path& log_file) {
  std::ifstream in(log_file);
  std::vector<std::string> lines;
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  std::string text;
  for (std::size_t i = lines.size() > kTailLines ? lines.size() - kTailLines : 0; i < lines.size();
       ++i) {
    text += "\n  " + lines[i];
  }
  return text.empty() ? " (none)" : text;
}

std::string ControllerSession::log_tail() const { return controller_log_tail(log_file_); }

std::optional<int> ControllerSession::finish(const std::string& why) {
  if (process_->running()) {
    link_->send_stop_request(v1::FAULT_CAUSE_OPERATOR, why);
    service_->serve_link(std::chrono::steady_clock::now() + std::chrono::milliseconds(50));
  }
  return process_->stop(std::chrono::seconds(3));
}

}  // namespace safecell
