#pragma once
// `safecell validate --closed-loop`: the whole system in simulated time (lockstep_scenario.hpp)
// over many random scenarios: a robot task and a person walking in (straight at the robot,
// reaching into its sweep, or across the cell) at up to 1.6 m/s. The ground truth is FCL between
// the simulated robot's own joints at every controller cycle and the person: a contact while the
// robot moves is a failure (VALIDATION.md). Each task is also run without people, for the
// productivity figure. The negative control (`--negative-control look-ahead-off`) switches the
// controller's look-ahead off: the same run must then find contacts while moving.

#include <cstdint>
#include <ostream>
#include <string>

namespace safecell {

struct ClosedLoopValidateOptions {
  std::string cell_path;     // empty: the built-in default cell
  std::string lut_cache;     // empty: the default cache folder
  int camera_threshold = 0;  // 0: the cell's
  std::size_t scenarios = 20;
  std::uint64_t seed = 1;
  std::size_t first = 0;  // the index of the first scenario (to run one again alone)
  double fps = 30.0;
  double latency_ms = 20.0;
  double max_seconds = 30.0;
  std::size_t task_pool = 8;
  bool look_ahead_off = false;  // --negative-control look-ahead-off
  bool separation_off = false;  // --negative-control separation-off: the cell's turned off
  std::string out_dir = "safecell-closed-loop";
  std::string controller_program;  // empty: found (find_controller_program)
  bool trace = false;              // a CSV per scenario (every cycle) into out_dir
  bool json = false;
};

// Returns the exit code: 0, or kExitValidationFailed when the robot touched a person while moving.
int run_closed_loop_validate(const ClosedLoopValidateOptions& options, std::ostream& out,
                             std::ostream& err);

}  // namespace safecell
