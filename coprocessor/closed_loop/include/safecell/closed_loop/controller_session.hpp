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

#include "safecell/cell/cell_model.hpp"
#include "safecell/closed_loop/controller_process.hpp"
#include "safecell/closed_loop/controller_setup.hpp"
#include "safecell/link/coprocessor_link.hpp"
#include "safecell/link/udp_transport.hpp"
#include "safecell/service/sensing_service.hpp"

namespace safecell {

struct ControllerSessionSettings {
  std::filesystem::path program;  // safecell-controller (find_controller_program)
  std::filesystem::path folder;   // controller.yaml and controller.log go here
  double fps = 30.0;              // the map rate the handshake announces
  double sync_error_s = 0.002;    // the pipeline's removal allowance for timing (FusionSettings)
  std::vector<std::string> extra_args;
  ProcessChannel channel = ProcessChannel::kLogOnly;  // kCommandPipes with --lockstep
  CoprocessorLink::Clock clock;                       // the link's; the steady clock if empty
  // Called once the program has started, before the link opens (a lockstep driver reads the
  // program's first line here and sets its clock).
  std::function<void(ControllerProcess&)> on_started;
};

// The settings of a session in real time (the program's output into its log, the steady clock).
ControllerSessionSettings real_time_session(const std::filesystem::path& program,
                                            const std::filesystem::path& folder, double fps,
                                            double sync_error_s);

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

 private:
  ControllerSetup setup_;
  std::filesystem::path log_file_;
  UdpTransport transport_;
  std::unique_ptr<ControllerProcess> process_;
  std::unique_ptr<CoprocessorLink> link_;
  std::unique_ptr<SensingService> service_;
};

}  // namespace safecell
