#pragma once
// The coprocessor's end of the lockstep channel to `safecell-controller --lockstep` (the program's
// stdin and stdout; the commands and answers are those of controller/host's lockstep_runner.hpp,
// whose text is the contract): simulated time for the closed-loop validation. The link itself
// stays real UDP; this channel only moves the controller's clock and reports its simulated robot's
// joints at every cycle, the ground truth of where the robot was.

#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "safecell/closed_loop/controller_process.hpp"

namespace safecell {

// The simulated robot at one controller cycle, in the controller's clock.
struct TruthSample {
  std::uint64_t time_ns = 0;
  std::string state;  // waiting, moving, slowed, stopped, fault
  double speed_scale = 0.0;
  std::vector<double> q;         // rad
  std::vector<double> velocity;  // rad/s
};

struct LockstepStep {
  std::vector<TruthSample> cycles;
  std::optional<std::string> ended;   // the task's outcome, when it ended in this step
  std::uint64_t controller_sent = 0;  // datagrams the controller has sent so far
};

class LockstepController {
 public:
  // Reads the program's `ready` line. Throws ClosedLoopSetupError (with `log_tail()`) when the
  // program does not answer as the contract says: an older program, or one that failed to start.
  LockstepController(ControllerProcess& process, std::size_t joint_count,
                     std::function<std::string()> log_tail);

  [[nodiscard]] std::uint64_t start_ns() const { return start_ns_; }
  // Runs the controller up to until_ns, after it has taken in the `sent` datagrams this end has
  // sent in all. Throws ClosedLoopSetupError on a broken answer.
  LockstepStep advance(std::uint64_t until_ns, std::uint64_t sent);
  void acknowledge();
  // Ends the program (quit); returns its cycle count.
  std::uint64_t quit();

 private:
  [[noreturn]] void fail(const std::string& what) const;
  std::string next_line(const char* expected);

  ControllerProcess& process_;
  std::size_t joint_count_;
  std::function<std::string()> log_tail_;
  std::uint64_t start_ns_ = 0;
};

}  // namespace safecell
