#pragma once
// `safecell controller config`: a safecell-controller configuration for a cell. The grid is the
// coprocessor's to the last bit and the LUT fingerprint that of the cell's tables (built or taken
// from the cache), so that the session opens; the link's addresses are the options'. The robot,
// timing and task sections hold the simulated robot's values (from the URDF's speed limits) as a
// start: an integrator replaces them with the real robot's.

#include <ostream>
#include <string>

namespace safecell {

struct ControllerConfigOptions {
  std::string cell_path;                        // empty: the built-in default cell
  std::string lut_cache;                        // empty: the default cache folder
  std::string listen = "0.0.0.0:47701";         // the controller's link address
  std::string coprocessor = "127.0.0.1:47700";  // where `safecell run` listens
  std::string out = "controller.yaml";
};

// Writes the file atomically and says what it holds.
void run_controller_config(const ControllerConfigOptions& options, std::ostream& out,
                           std::ostream& err);

}  // namespace safecell
