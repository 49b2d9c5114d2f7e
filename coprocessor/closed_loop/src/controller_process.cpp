#include "safecell/closed_loop/controller_process.hpp"

#include "safecell/closed_loop/controller_setup.hpp"

#include <signal.h>

#include <boost/process/args.hpp>
#include <boost/process/child.hpp>
#include <boost/process/io.hpp>
#include <stdexcept>
#include <system_error>
#include <thread>

namespace safecell {

struct ControllerProcess::Child {
  boost::process::child process;
};

ControllerProcess::ControllerProcess(const std::filesystem::path& program,
                                     const std::vector<std::string>& args,
                                     const std::filesystem::path& log_file) {
  std::error_code error;
  std::filesystem::remove(log_file, error);  // the output of an earlier run would mislead
  child_ = std::make_unique<Child>(Child{
      boost::process::child(program.string(), boost::process::args(args),
                            (boost::process::std_out & boost::process::std_err) > log_file.string(),
                            boost::process::std_in.close(), error)});
  if (error) {
    throw ClosedLoopSetupError("could not start " + program.string() + ": " + error.message());
  }
}

ControllerProcess::~ControllerProcess() { (void)stop(std::chrono::milliseconds(2000)); }

bool ControllerProcess::running() {
  if (!child_ || exit_code_) return false;
  std::error_code error;
  if (child_->process.running(error)) return true;
  exit_code_ = child_->process.exit_code();
  return false;
}

void ControllerProcess::acknowledge_fault() {
  if (running()) ::kill(child_->process.id(), SIGUSR1);
}

std::optional<int> ControllerProcess::stop(std::chrono::milliseconds grace) {
  if (!running()) return exit_code_;
  ::kill(child_->process.id(), SIGTERM);
  const auto deadline = std::chrono::steady_clock::now() + grace;
  while (std::chrono::steady_clock::now() < deadline) {
    if (!running()) return exit_code_;
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  std::error_code error;
  child_->process.terminate(error);  // SIGKILL
  child_->process.wait(error);
  return std::nullopt;
}

}  // namespace safecell
