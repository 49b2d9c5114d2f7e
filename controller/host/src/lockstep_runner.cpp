#include "safecell/controller/host/lockstep_runner.hpp"

#include <poll.h>
#include <unistd.h>

#include <cmath>
#include <cstdint>
#include <optional>
#include <ostream>
#include <sstream>
#include <string>

namespace safecell {
namespace {

constexpr int kAnnouncedDatagramsWait_ms = 5000;

// Lines from a descriptor, read as they come; while none is complete, the module's link is
// served (datagrams handled at the module's current time).
class CommandReader {
 public:
  CommandReader(ControllerModule& module, int fd) : module_(module), fd_(fd) {}

  // The next line; nullopt when the channel has closed.
  std::optional<std::string> next() {
    for (;;) {
      const std::size_t newline = buffer_.find('\n');
      if (newline != std::string::npos) {
        std::string line = buffer_.substr(0, newline);
        buffer_.erase(0, newline + 1);
        return line;
      }
      pollfd waiting[2] = {{fd_, POLLIN, 0}, {module_.socket_fd(), POLLIN, 0}};
      if (::poll(waiting, 2, -1) < 0) continue;  // EINTR
      if ((waiting[1].revents & POLLIN) != 0) module_.service_link(module_.now_ns() + 1);
      if ((waiting[0].revents & (POLLIN | POLLHUP)) != 0) {
        char chunk[4096];
        const ssize_t got = ::read(fd_, chunk, sizeof chunk);
        if (got <= 0) return std::nullopt;
        buffer_.append(chunk, static_cast<std::size_t>(got));
      }
    }
  }

 private:
  ControllerModule& module_;
  int fd_;
  std::string buffer_;
};

// Takes in datagrams until `announced` have come; false when they do not come in time.
bool take_in(ControllerModule& module, std::uint64_t announced) {
  int waited_ms = 0;
  for (;;) {
    module.service_link(module.now_ns() + 1);
    if (module.datagrams_received() >= announced) return true;
    if (waited_ms >= kAnnouncedDatagramsWait_ms) return false;
    pollfd waiting{module.socket_fd(), POLLIN, 0};
    (void)::poll(&waiting, 1, 10);
    waited_ms += 10;
  }
}

void write_cycle(std::ostream& out, std::uint64_t now, const ModuleStatus& status,
                 const RobotJoints& joints) {
  out << "cycle " << now << ' ' << (status.cycle ? to_string(status.cycle->state) : "waiting")
      << ' ' << (status.cycle ? status.cycle->speed_scale : 0.0);
  for (std::uint32_t j = 0; j < joints.joint_count; ++j) out << ' ' << joints.position_rad[j];
  for (std::uint32_t j = 0; j < joints.joint_count; ++j) out << ' ' << joints.velocity_rad_s[j];
  out << '\n';
}

}  // namespace

int run_lockstep(ControllerModule& module, double period_ms, int command_fd, std::ostream& out,
                 std::ostream& log) {
  const auto period_ns = static_cast<std::uint64_t>(std::llround(period_ms * 1e6));
  // Simulated time starts at 1 s: 0 means "not reported" in the protocol's time fields.
  const std::uint64_t start_ns = 1'000'000'000u;
  module.set_time_ns(start_ns);
  module.begin(start_ns);
  out.precision(17);
  out << "ready " << start_ns << std::endl;
  CommandReader reader(module, command_fd);
  std::uint64_t next_cycle_ns = start_ns + period_ns;
  bool ended = false;
  while (const std::optional<std::string> line = reader.next()) {
    std::istringstream command(*line);
    std::string verb;
    command >> verb;
    if (verb == "quit") {
      out << "bye " << module.status().cycles << std::endl;
      return 0;
    }
    if (verb == "acknowledge") {
      module.acknowledge();
      continue;
    }
    std::uint64_t until_ns = 0;
    std::uint64_t announced = 0;
    if (verb != "advance" || !(command >> until_ns >> announced) || until_ns < module.now_ns()) {
      log << "safecell-controller: lockstep: command '" << *line
          << "' not understood; expected 'advance <until_ns> <datagrams>' (time not going back), "
             "'acknowledge' or 'quit'\n";
      return 2;
    }
    if (!take_in(module, announced)) {
      log << "safecell-controller: lockstep: " << announced << " datagrams announced, "
          << module.datagrams_received() << " came within " << kAnnouncedDatagramsWait_ms
          << " ms\n";
      return 2;
    }
    while (!ended && next_cycle_ns <= until_ns) {
      module.set_time_ns(next_cycle_ns);
      ended = module.cycle(next_cycle_ns);
      write_cycle(out, next_cycle_ns, module.status(), module.robot_joints());
      if (ended) out << "end " << to_string(module.outcome()) << '\n';
      next_cycle_ns += period_ns;
      module.service_link(next_cycle_ns);  // nothing new arrives: the driver waits for `at`
    }
    module.set_time_ns(until_ns);
    out << "at " << until_ns << ' ' << module.datagrams_sent() << std::endl;
  }
  log << "safecell-controller: lockstep: the command channel closed\n";
  return 2;
}

}  // namespace safecell
