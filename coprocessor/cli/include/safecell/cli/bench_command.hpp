#pragma once
// `safecell bench`: the project's benchmarks on the default cell, as a table or one JSON object.

#include <ostream>

namespace safecell {

struct BenchOptions {
  bool json = false;
  bool quick = false;  // shorter runs (CI smoke); figures are noisier
};

void run_bench(const BenchOptions& options, std::ostream& out, std::ostream& progress);

}  // namespace safecell
