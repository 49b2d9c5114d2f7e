#pragma once
// `safecell cell coverage`: where on the floor a person stands that too few cameras see
// (floor_coverage.hpp), as a floor plan (PNG) and figures: the share of the robot's reach that
// is blind.

#include <ostream>
#include <string>

namespace safecell {

struct CellCoverageOptions {
  std::string cell_path;  // empty: the built-in default cell
  std::string out_dir = "coverage";
  double step_m = 0.1;
  bool json = false;
};

// Writes <out>/floor_coverage.png and <out>/coverage.json, prints the figures.
void run_cell_coverage(const CellCoverageOptions& options, std::ostream& out, std::ostream& err);

}  // namespace safecell
