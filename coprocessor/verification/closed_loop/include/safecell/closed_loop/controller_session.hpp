#pragma once
// A session with a safecell-controller process on this machine: its configuration written for the
// cell (controller.yaml, the link's ports filled in), the program started (its output in
// controller.log), the link opened (the handshake and the clock echoes, waiting while the
// program starts), and the coprocessor's sensing service on that link. finish() asks the
// controller to stop (it holds the robot) and ends the program.

#include <cstdint>
#include <filesystem>
#include <functional>
#include <memory>
#include <optional>
#include <ostream>
#include <string>
#include <vector>

#include <opencv2/core.hpp>

#include "safecell/cell/cell_model.hpp"
#include "safecell/closed_loop/controller_process.hpp"
#include "safecell/closed_loop/controller_setup.hpp"
#include "safecell/link/coprocessor_link.hpp"
#include "safecell/link/udp_transport.hpp"
#include "safecell/service/sensing_service.hpp"

namespace safecell {

// Where each end sends, when something sits between them (a fault-injecting proxy).
struct LinkRoute {
  std::uint16_t coprocessor_sends_to = 0;  // on 127.0.0.1
  std::uint16_t controller_sends_to = 0;
};

struct ControllerSessionSettings {
  std::filesystem::path program;  // safecell-controller (find_controller_program)
  // Per camera of the cell, the empty cell's image: the cameras' health checks (camera_views.hpp)
  // compare each frame with it.
  std::vector<cv::Mat> camera_references;
  std::filesystem::path folder;  // controller.yaml and controller.log go here
  double fps = 30.0;             // the map rate the handshake announces
  double sync_error_s = 0.002;   // the pipeline's removal allowance for timing (FusionSettings)
  std::vector<std::string> extra_args;
  ProcessChannel channel = ProcessChannel::kLogOnly;  // kCommandPipes with --lockstep
  CoprocessorLink::Clock clock;                       // the link's; the steady clock if empty
  // Called once the program has started, before the link opens (a lockstep driver reads the
  // program's first line here and sets its clock).
  std::function<void(ControllerProcess&)> on_started;
  // Given both ends' ports, where each is to send; straight to the other when empty.
  std::function<LinkRoute(std::uint16_t coprocessor_port, std::uint16_t controller_port)> route;
  // The LUT fingerprint written into the controller's file, when not the coprocessor's (a fault
  // campaign's controller commissioned with other tables: it must refuse the session).
  std::optional<std::uint64_t> controller_lut_fingerprint;
  // The service's (sensing_service.hpp): make the pipeline's map also when the separation stops
  // the robot.
  bool maps_of_stopped_cycles = false;
};

// The settings of a session in real time (the program's output into its log, the steady clock).
ControllerSessionSettings real_time_session(const std::filesystem::path& program,
                                            const std::filesystem::path& folder, double fps,
                                            double sync_error_s,
                                            std::vector<cv::Mat> camera_references);

// The last lines of a controller's log file, indented, for error messages (" (none)" if empty).
std::string controller_log_tail(const std::filesystem::path& log_file);

class ControllerSession {
 public:
  // Throws ClosedLoopSetupError (the program missing or not starting) or LinkSetupError (no
  // session within 10 s, or refused), the latter with the controller's last lines of output.
  ControllerSession(const CellModel& cell, const CspaceGrid& grid, SensingPipeline& pipeline,
                    std::uint64_t lut_fingerprint, ControllerSetup setup,
                    const ControllerSessionSettings& settings, std::ostream& log);
  ~ControllerSession();
  ControllerSession(const ControllerSession&) = delete;
  ControllerSession& operator=(const ControllerSession&) = delete;

  [[nodiscard]] CoprocessorLink& link() { return *link_; }
  [[nodiscard]] SensingService& service() { return *service_; }
  [[nodiscard]] ControllerProcess& process() { return *process_; }
  [[nodiscard]] const ControllerSetup& setup() const { return setup_; }
  [[nodiscard]] const std::filesystem::path& log_file() const { return log_file_; }
  [[nodiscard]] const UdpTransport& transport() const { return transport_; }
  // The last lines of the controller's output, for error messages.
  [[nodiscard]] std::string log_tail() const;

  // A stop request (when the program still runs), then the program's end; its exit code, or
  // nullopt when it had to be killed.
  std::optional<int> finish(const std::string& why);

  // What a controller's peer sees of a restarted controller: the program killed (SIGKILL), the
  // same configuration started again with `extra_args`, its output into the next log file. The
  // link is not reopened here (the new program knows no session until reopen_link()).
  void restart_controller(const std::vector<std::string>& extra_args);
  // What a controller sees of a coprocessor that died and started again: this link abandoned
  // without a word, a new one (a new session) opened to the same controller, a new sensing
  // service on it. Handlers given to link().on_joint_state() before must be given again.
  // Throws LinkSetupError as the constructor does.
  void reopen_link();

 private:
  void start_program(const std::vector<std::string>& extra_args);
  void open_link();

  CoprocessorLinkConfig link_config_;
  SensingServiceSettings service_settings_;
  SensingPipeline& pipeline_;
  const CellModel& cell_;
  const CspaceGrid& grid_;
  std::ostream& log_;
  ControllerSessionSettings settings_;
  std::filesystem::path config_file_;
  int restarts_ = 0;
  ControllerSetup setup_;
  std::filesystem::path log_file_;
  UdpTransport transport_;
  std::unique_ptr<ControllerProcess> process_;
  std::unique_ptr<CoprocessorLink> link_;
  std::unique_ptr<SensingService> service_;
};

}  // namespace safecell
