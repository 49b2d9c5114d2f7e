#include "safecell/reference/random_configurations.hpp"

#include <random>
#include <stdexcept>
#include <string>

namespace safecell {

std::vector<std::vector<double>> random_configurations(
    const std::vector<std::array<double, 2>>& ranges, std::size_t count, std::uint64_t seed) {
  for (std::size_t j = 0; j < ranges.size(); ++j) {
    if (!(ranges[j][0] <= ranges[j][1])) {
      throw std::invalid_argument("random_configurations: range of joint " + std::to_string(j) +
                                  " is reversed");
    }
  }
  std::mt19937_64 rng(seed);
  std::vector<std::vector<double>> configurations(count);
  for (auto& q : configurations) {
    for (const auto& range : ranges) {
      q.push_back(std::uniform_real_distribution<double>(range[0], range[1])(rng));
    }
  }
  return configurations;
}

}  // namespace safecell
