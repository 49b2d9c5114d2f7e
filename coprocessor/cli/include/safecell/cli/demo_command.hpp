#pragma once
// `safecell demo`, first form (the controller joins in a later issue): the built-in simulated
// cell with the robot moving and a person walking in, close to the arm and out again; the whole
// sensing pipeline on every frame with a live status line; a report folder with camera views,
// forbidden-map slices over time, the cameras' observability and summary.json (cycles, times,
// forbidden cells, and collisions missed against the FCL ground truth, which must be 0).

#include <cstdint>
#include <ostream>
#include <string>

namespace safecell {

struct DemoOptions {
  std::string cell_path;  // empty: the built-in default cell
  double seconds = 8.0;
  double fps = 10.0;
  std::string out_dir = "safecell-demo";
  std::string lut_cache;  // empty: the default cache folder
  std::uint64_t seed = 1;
  int views_every = 10;               // cycles between saved pictures
  std::size_t checks_per_cycle = 60;  // robot configurations checked against ground truth
};

// Returns the exit code: 0, or kExitValidationFailed (validate_command.hpp) when a collision
// with a seen obstacle was not forbidden.
int run_demo(const DemoOptions& options, std::ostream& out, std::ostream& err);

}  // namespace safecell
