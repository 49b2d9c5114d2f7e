#pragma once
// safecell-controller as a child process: started with its configuration file, its output into
// a log file; stopped with SIGTERM (the module stops the robot and exits), killed only when it
// does not exit in time. The destructor stops a process still running, and the program gets
// SIGTERM when this process dies, however it dies: it never outlives it.

#include <chrono>
#include <cstdint>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace safecell {

// How the program's standard streams are connected.
enum class ProcessChannel : std::uint8_t {
  kLogOnly,       // stdout and stderr into the log file, stdin closed
  kCommandPipes,  // stdin and stdout are pipes to this process (lockstep), stderr the log file
};

class ControllerProcess {
 public:
  // Throws ClosedLoopSetupError naming the program when it cannot be started.
  ControllerProcess(const std::filesystem::path& program, const std::vector<std::string>& args,
                    const std::filesystem::path& log_file,
                    ProcessChannel channel = ProcessChannel::kLogOnly);
  ~ControllerProcess();
  ControllerProcess(const ControllerProcess&) = delete;
  ControllerProcess& operator=(const ControllerProcess&) = delete;

  [[nodiscard]] bool running();
  [[nodiscard]] int pid() const;
  // kCommandPipes only: a line to the program's stdin (flushed), the next line of its stdout
  // (blocks; nullopt once it has closed it).
  void write_line(const std::string& line);
  std::optional<std::string> read_line();
  // The operator's acknowledgement of a latched fault (SIGUSR1 to safecell-controller).
  void acknowledge_fault();
  // SIGTERM, then waits up to `grace` for the exit; kills it after that. Returns the exit code
  // (nullopt when it had to be killed).
  std::optional<int> stop(std::chrono::milliseconds grace);
  // SIGKILL at once: the program gets no chance to tidy up (what a crash looks like to its peer).
  void kill();
  // The exit code once it has exited by itself.
  [[nodiscard]] std::optional<int> exit_code() const { return exit_code_; }

 private:
  struct Child;
  std::unique_ptr<Child> child_;
  std::optional<int> exit_code_;
};

}  // namespace safecell
