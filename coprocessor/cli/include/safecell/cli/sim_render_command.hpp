#pragma once
// `safecell sim render`: what every camera of the simulated cell sees for one robot
// configuration and a few humans, as PNG files, with the ground truth of that moment.

#include <optional>
#include <ostream>
#include <string>
#include <vector>

namespace safecell {

struct SimRenderOptions {
  std::string cell_path;            // empty: the built-in default cell
  std::string q_deg;                // "a,b,c,..." joint values in degrees
  std::string q_rad;                // or in radians (exactly one of the two)
  std::vector<std::string> humans;  // each "x,y" or "x,y,heading_deg" on the floor, metres
  std::string out_dir;
  std::uint64_t seed = 1;
  double noise_sigma = 2.0;
  bool visual = false;  // show the robot's visual geometry instead of its collision geometry
};

// Throws CellError for an unusable cell and std::invalid_argument (message naming the option and
// value) for bad options; writes each PNG atomically.
void run_sim_render(const SimRenderOptions& options, std::ostream& out);

}  // namespace safecell
