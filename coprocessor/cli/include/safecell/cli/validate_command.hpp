#pragma once
// `safecell validate`: the sensing pipeline against FCL ground truth on random simulated scenes
// (ground_truth_validation.hpp). Exits with kExitValidationFailed when a collision was missed.

#include <cstdint>
#include <ostream>
#include <string>
#include <vector>

namespace safecell {

inline constexpr int kExitValidationFailed = 1;

struct ValidateOptions {
  std::string cell_path;  // empty: the built-in default cell
  std::size_t scenes = 200;
  std::uint64_t seed = 1;
  std::size_t configurations = 400;  // per scene
  int humans = 2;                    // at most, per uniform scene
  int objects = 1;                   // boxes, at most, per uniform scene
  std::string removal = "occlusion-aware";
  std::string negative_control = "none";
  // The tables and fusion under test (ablations); unset: the cell's and the defaults.
  double padding_m = 0.02;
  double ball_radius_m = 0.0;  // size of the balls covering the robot; 0: the cell's
  std::string robot_parts;     // the parts the cameras vote on (robot_parts.hpp); empty: the cell's
  bool hidden_votes = false;   // the robot's blocked pixels vote as hidden
  int occlusion_reach = -1;    // feature cells a blob grows into the robot; < 0: the cell's
  double m_max_m = 0.0;        // 0: the cell's
  double envelope_max_move_m = 0.0;  // sub-cells' max-move of the envelope; 0: the cell's
  int camera_threshold = 0;          // 0: the cell's
  // Model error applied to the simulated world (model_error.hpp); --model-error sets the
  // documented tolerances, the single options override them.
  bool documented_model_error = false;
  double camera_rotation_error_deg = -1.0;  // < 0: unset
  double camera_translation_error_m = -1.0;
  double focal_error = -1.0;
  double lens_k1 = 0.0;
  bool lens_k1_set = false;
  double robot_growth_m = -1.0;
  std::size_t traced_per_scene = 2;  // needless stops traced to a cause per scene
  std::string shard = "1/1";         // K/N: the K-th of N parts of the scenes
  unsigned threads = 0;              // 0: one per core
  std::string lut_cache;             // empty: the default cache folder
  bool json = false;
};

// Returns the exit code: 0, or kExitValidationFailed when `missed` > 0.
int run_validate(const ValidateOptions& options, std::ostream& out, std::ostream& err);

struct ValidateMergeOptions {
  std::vector<std::string> files;  // JSON reports of `safecell validate --json`
  bool json = false;
};

// Adds the reports of shards of one run into the report of the run. Throws std::invalid_argument
// (exit 2) for a file that is not such a report, or reports of different runs or the same shard.
// Returns as run_validate() does.
int run_validate_merge(const ValidateMergeOptions& options, std::ostream& out);

}  // namespace safecell
