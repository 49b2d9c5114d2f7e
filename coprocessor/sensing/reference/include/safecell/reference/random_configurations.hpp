#pragma once
// Candidate robot configurations for the reference images: spread over the joints' ranges.

#include <array>
#include <cstdint>
#include <vector>

namespace safecell {

// `count` configurations, each joint drawn uniformly from its [lo, hi] range (same unit as the
// ranges), the same for the same seed. Throws std::invalid_argument for a reversed range.
std::vector<std::vector<double>> random_configurations(
    const std::vector<std::array<double, 2>>& ranges, std::size_t count, std::uint64_t seed);

}  // namespace safecell
