#pragma once
// The p-th percentile of timings, for p99 figures.

#include <vector>

namespace safecell {

// The value below or at which `share` (0..1] of the values lie (nearest rank); 0 when empty.
[[nodiscard]] double percentile(std::vector<double> values, double share);

}  // namespace safecell
