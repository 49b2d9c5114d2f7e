#include "safecell/closed_loop/lockstep_controller.hpp"

#include <sstream>

#include "safecell/closed_loop/controller_setup.hpp"

namespace safecell {

LockstepController::LockstepController(ControllerProcess& process, std::size_t joint_count,
                                       std::function<std::string()> log_tail)
    : process_(process), joint_count_(joint_count), log_tail_(std::move(log_tail)) {
  std::istringstream ready(next_line("ready <ns>"));
  std::string verb;
  if (!(ready >> verb >> start_ns_) || verb != "ready") fail("expected 'ready <ns>'");
}

void LockstepController::fail(const std::string& what) const {
  throw ClosedLoopSetupError("the controller's lockstep channel: " + what +
                             " (is the program built from this source?); its last words:" +
                             (log_tail_ ? log_tail_() : std::string(" -")));
}

std::string LockstepController::next_line(const char* expected) {
  std::optional<std::string> line = process_.read_line();
  if (!line) fail(std::string("closed while waiting for '") + expected + "'");
  return *line;
}

LockstepStep LockstepController::advance(std::uint64_t until_ns, std::uint64_t sent) {
  process_.write_line("advance " + std::to_string(until_ns) + " " + std::to_string(sent));
  LockstepStep step;
  for (;;) {
    const std::string line = next_line("cycle, end or at");
    std::istringstream in(line);
    std::string verb;
    in >> verb;
    if (verb == "cycle") {
      TruthSample sample;
      sample.q.resize(joint_count_);
      sample.velocity.resize(joint_count_);
      in >> sample.time_ns >> sample.state >> sample.speed_scale;
      for (double& q : sample.q) in >> q;
      for (double& v : sample.velocity) in >> v;
      if (!in)
        fail("a cycle line with fewer than " + std::to_string(joint_count_) + " joints: '" + line +
             "'");
      step.cycles.push_back(std::move(sample));
    } else if (verb == "end") {
      std::string outcome;
      std::getline(in >> std::ws, outcome);
      step.ended = outcome;
    } else if (verb == "at") {
      std::uint64_t at = 0;
      if (!(in >> at >> step.controller_sent) || at != until_ns) {
        fail("'" + line + "' after advance " + std::to_string(until_ns));
      }
      return step;
    } else {
      fail("unexpected '" + line + "'");
    }
  }
}

void LockstepController::acknowledge() { process_.write_line("acknowledge"); }

std::uint64_t LockstepController::quit() {
  process_.write_line("quit");
  std::istringstream bye(next_line("bye <cycles>"));
  std::string verb;
  std::uint64_t cycles = 0;
  if (!(bye >> verb >> cycles) || verb != "bye") fail("expected 'bye <cycles>'");
  return cycles;
}

}  // namespace safecell
