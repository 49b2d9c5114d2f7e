#pragma once
// `safecell validate`: the sensing pipeline against FCL ground truth on random simulated scenes
// (ground_truth_validation.hpp). Exits with kExitValidationFailed when a collision was missed.

#include <cstdint>
#include <ostream>
#include <string>

namespace safecell {

inline constexpr int kExitValidationFailed = 1;

struct ValidateOptions {
  std::string cell_path;  // empty: the built-in default cell
  std::size_t scenes = 200;
  std::uint64_t seed = 1;
  std::size_t configurations = 400;  // per scene
  int humans = 2;                    // at most, per scene
  int objects = 1;                   // boxes, at most, per scene
  std::string removal = "occlusion-aware";
  std::string lut_cache;  // empty: the default cache folder
  bool json = false;
};

// Returns the exit code: 0, or kExitValidationFailed when `missed` > 0.
int run_validate(const ValidateOptions& options, std::ostream& out, std::ostream& err);

}  // namespace safecell
