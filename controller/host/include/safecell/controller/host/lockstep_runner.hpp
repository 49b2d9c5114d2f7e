#pragma once
// The controller module in simulated time, stepped by the closed-loop validation (safecell
// validate --closed-loop): the module's clock moves only when the driver says, so that the whole
// loop (cameras, pipeline, link, controller, robot) runs at whatever speed the machine manages
// and gives the same result on any machine. The link stays real: UDP datagrams in the real
// protocol. The driver talks to this runner on a text channel (the program's stdin and stdout).
//
// The runner first writes `ready <now_ns>`. Then, one command per line:
//   advance <until_ns> <sent>   <sent>: datagrams the driver has sent to the controller so far.
//                               The runner takes in that many (each handled at the current time,
//                               as it would be on arrival), then runs every cycle due up to
//                               until_ns (the robot advanced to each), handling the link between
//                               them, and sets the clock to until_ns. It answers a line per cycle
//                               `cycle <t_ns> <state> <speed_scale> <q_1..q_n> <dq_1..dq_n>` (the
//                               simulated robot's own joints at that cycle, rad and rad/s: the
//                               ground truth), `end <outcome>` when the task ended in that step,
//                               and last `at <until_ns> <sent>` with the datagrams it has sent.
//   acknowledge                 the operator's acknowledgement of a latched fault
//   quit                        answers `bye <cycles>` and ends
// While waiting for a command it handles datagrams as they come, at the current time.
// Thread context: the program's main thread.

#include <iosfwd>

#include "safecell/controller/host/controller_module.hpp"

namespace safecell {

// Returns the program's exit code: 0 after quit, 2 when the channel closes, a command is not
// understood, or the datagrams announced do not come within 5 s (the message names it on `log`).
int run_lockstep(ControllerModule& module, double period_ms, int command_fd, std::ostream& out,
                 std::ostream& log);

}  // namespace safecell
