#pragma once
// `safecell luts record` and `safecell luts check`: recorded mode (recorded_silhouettes.hpp), with
// the simulated cell standing in for the real robot and cameras until the coprocessor can drive
// a robot. `record` builds a recorded LUT file; `check` compares what the cameras see of the
// robot with the model's silhouettes and flags a camera whose calibration is off.

#include <ostream>
#include <string>

namespace safecell {

struct LutsRecordOptions {
  std::string cell_path;  // empty: the built-in default cell
  std::string out_dir;    // `record` only
  int key_stride = 2;
  int wrist_samples = 3;
  double padding_m = 0.02;
  double min_coverage = 0.95;  // `check` only
  bool json = false;
};

inline constexpr int kExitCameraFlagged = 1;

// Throws std::invalid_argument (as build_recorded_luts()) when a camera is too close for the
// recording's bound.
void run_luts_record(const LutsRecordOptions& options, std::ostream& out, std::ostream& err);
// Returns 0, or kExitCameraFlagged when some camera's coverage is below min_coverage.
int run_luts_check(const LutsRecordOptions& options, std::ostream& out, std::ostream& err);

}  // namespace safecell
