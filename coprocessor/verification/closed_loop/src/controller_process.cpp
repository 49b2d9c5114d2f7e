#include "safecell/closed_loop/controller_process.hpp"

#include "safecell/closed_loop/controller_setup.hpp"

#include <signal.h>
#include <sys/prctl.h>
#include <unistd.h>

#include <cerrno>

#include <boost/process/args.hpp>
#include <boost/process/child.hpp>
#include <boost/process/extend.hpp>
#include <boost/process/io.hpp>
#include <boost/process/pipe.hpp>
#include <stdexcept>
#include <system_error>
#include <thread>

namespace safecell {

// The pipes as plain descriptors, read and written with POSIX calls (Boost's pipe streams would
// do as well, but their stream buffers flush from a destructor, which the analyzer refuses).
struct ControllerProcess::Child {
  boost::process::pipe commands;
  boost::process::pipe answers;
  std::string pending;  // read from `answers`, not yet a whole line
  boost::process::child process;
};

namespace {

// The program must not outlive this process: a `safecell demo` killed with SIGKILL left
// safecell-controller running, at real-time priority, holding its UDP port. The kernel sends it
// SIGTERM (it stops the robot and exits) when the thread that started it ends (PR_SET_PDEATHSIG:
// the thread, not the process; every caller starts it from its main thread). A parent that died
// before the setting took hold is seen in the parent id. Runs in the child between fork and exec.
auto die_with_parent() {
  const pid_t parent = ::getpid();
  return boost::process::extend::on_exec_setup([parent](auto& /*executor*/) {
    if (::prctl(PR_SET_PDEATHSIG, SIGTERM) != 0 || ::getppid() != parent) ::_exit(127);
  });
}

}  // namespace

ControllerProcess::ControllerProcess(const std::filesystem::path& program,
                                     const std::vector<std::string>& args,
                                     const std::filesystem::path& log_file,
                                     ProcessChannel channel) {
  namespace bp = boost::process;
  std::error_code error;
  std::filesystem::remove(log_file, error);  // the output of an earlier run would mislead
  child_ = std::make_unique<Child>();
  if (channel == ProcessChannel::kCommandPipes) {
    // A program that has died closes its pipe: writing to it must fail, not kill this process.
    ::signal(SIGPIPE, SIG_IGN);
    child_->process = bp::child(program.string(), bp::args(args), bp::std_out > child_->answers,
                                bp::std_err > log_file.string(), bp::std_in < child_->commands,
                                die_with_parent(), error);
    // Boost.Process has handed the program its ends and closed them here: the program's exit
    // closes `answers` (read_line() then ends).
  } else {
    child_->process =
        bp::child(program.string(), bp::args(args), (bp::std_out & bp::std_err) > log_file.string(),
                  bp::std_in.close(), die_with_parent(), error);
  }
  if (error) {
    throw ClosedLoopSetupError("could not start " + program.string() + ": " + error.message());
  }
}

void ControllerProcess::write_line(const std::string& line) {
  const std::string text = line + "\n";
  std::size_t written = 0;
  while (written < text.size()) {
    const ssize_t n =
        ::write(child_->commands.native_sink(), text.data() + written, text.size() - written);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return;  // the program has gone: its answer will not come (read_line says so)
    written += static_cast<std::size_t>(n);
  }
}

std::optional<std::string> ControllerProcess::read_line() {
  for (;;) {
    const std::size_t newline = child_->pending.find('\n');
    if (newline != std::string::npos) {
      std::string line = child_->pending.substr(0, newline);
      child_->pending.erase(0, newline + 1);
      return line;
    }
    char chunk[4096];
    const ssize_t n = ::read(child_->answers.native_source(), chunk, sizeof chunk);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return std::nullopt;
    child_->pending.append(chunk, static_cast<std::size_t>(n));
  }
}

ControllerProcess::~ControllerProcess() { (void)stop(std::chrono::milliseconds(2000)); }

int ControllerProcess::pid() const { return child_->process.id(); }

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
  kill();
  return std::nullopt;
}

void ControllerProcess::kill() {
  if (!running()) return;
  std::error_code error;
  child_->process.terminate(error);  // SIGKILL
  child_->process.wait(error);
}

}  // namespace safecell
