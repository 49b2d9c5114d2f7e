#include "safecell/test/property.hpp"

#include <string>

namespace safecell::test {
namespace {

std::string reproduce_hint(std::uint64_t seed) {
  return "seed=" + std::to_string(seed) + " (reproduce with --seed=" + std::to_string(seed) + ")";
}

}  // namespace

PropertySettings& property_settings() {
  static PropertySettings settings;
  return settings;
}

PropertyRun::PropertyRun(int default_iterations)
    : seed_(property_settings().seed),
      default_iterations_(default_iterations),
      iterations_(property_settings().iterations > 0 ? property_settings().iterations
                                                     : default_iterations),
      rng_(seed_),
      trace_(__FILE__, __LINE__, reproduce_hint(seed_)) {}

}  // namespace safecell::test
