#pragma once
// `safecell demo`: the closed loop on one machine, in real time. The coprocessor (this process:
// the simulated cell's cameras, the sensing pipeline, the link) and safecell-controller (a child
// process: the controller core driving the simulated robot through a pick-and-place task with the
// safe gross-motion service) talk over loopback UDP in the real protocol. A person walks into the
// cell, towards the robot, reaches towards it, and leaves. A live status line; a report folder
// with the camera views, forbidden-map slices with the robot's path, the plot over time,
// summary.json and index.html. The ground truth (FCL) checks every joint sample of the robot
// against the person (contacts while moving must be 0) and a sample of configurations per checked
// frame against the map (missed must be 0).

#include <cstdint>
#include <ostream>
#include <string>

namespace safecell {

struct DemoOptions {
  std::string cell_path;  // empty: the built-in default cell
  double seconds = 60.0;
  double fps = 15.0;
  std::string out_dir = "safecell-demo";
  std::string lut_cache;  // empty: the default cache folder
  std::uint64_t seed = 1;
  double views_every_s = 2.0;         // seconds between saved camera views and slices (0: none)
  std::size_t checks_per_cycle = 12;  // configurations checked against the map per checked frame
  int check_every = 5;                // frames between checked frames
  std::string controller_program;     // empty: found (find_controller_program)
  // The demo's operator acknowledges a latched fault after it held this long (0: never).
  double acknowledge_after_s = 2.0;
  // The incident recorder keeps this many seconds before each stop or fault and writes them into
  // <out>/incidents for `safecell replay` (0: off).
  double incident_seconds = 2.0;
};

// Returns the exit code: 0, or kExitValidationFailed (validate_command.hpp) when the robot touched
// the person while moving or a collision with a seen person was not forbidden.
int run_demo(const DemoOptions& options, std::ostream& out, std::ostream& err);

}  // namespace safecell
