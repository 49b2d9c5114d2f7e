#pragma once
// `safecell bench`: the project's benchmarks on the default cell, as a table or one JSON object.

#include <ostream>
#include <string>

namespace safecell {

struct BenchOptions {
  bool json = false;
  bool quick = false;  // shorter runs (CI smoke); figures are noisier
  // With a cell file: only the fusion on that cell's grid against the default cell's
  // (cell_fusion_bench.hpp), over `frames` frames of the demo.
  std::string cell_path;
  std::string baseline_cell_path;  // empty: the built-in default cell
  int frames = 300;
  std::string lut_cache;  // empty: the default cache folder
};

void run_bench(const BenchOptions& options, std::ostream& out, std::ostream& progress);

}  // namespace safecell
