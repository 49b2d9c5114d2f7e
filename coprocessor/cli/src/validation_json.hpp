#pragma once
// The JSON of `safecell validate --json`, and reading it back for `safecell validate merge`:
// the additive counts of a report (ground_truth_validation.hpp) with the figures derived from
// them, and the run's settings that shards must share to be merged. Private to the CLI.

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "safecell/validation/ground_truth_validation.hpp"

namespace safecell {

// What a run was, besides its counts: shards of one run agree on all of it but the shard.
struct ValidationRun {
  std::uint64_t seed = 1;
  std::size_t scenes = 0;  // of the whole run
  std::size_t configurations_per_scene = 0;
  int camera_threshold = 2;
  std::string removal;
  std::string negative_control;
  double padding_m = 0.0;
  double ball_radius_m = 0.0;
  std::string robot_parts = "whole-robot";  // reports before the vote per part: the whole robot
  bool hidden_votes = false;                // reports before hidden votes had none
  int occlusion_reach = kDefaultOcclusionReach;  // feature cells; reports before it: the default
  double m_max_m = 0.0;
  std::uint32_t envelope_subdivision = 1;  // sub-cells per joint; reports before them: 1
  ModelError model_error;
  std::size_t shard_count = 1;
  std::vector<std::size_t> shards;  // which of them this report holds (1-based)
};

[[nodiscard]] nlohmann::ordered_json validation_json(const ValidationRun& run,
                                                     const ValidationReport& report);

// Whether two runs are shards of one run: everything but the shards agrees.
[[nodiscard]] bool same_run(const ValidationRun& a, const ValidationRun& b);

// Reads a report written by validation_json(). Throws std::invalid_argument naming `source`,
// the key and what was expected when the JSON is not such a report.
void read_validation_json(const nlohmann::json& json, const std::string& source, ValidationRun& run,
                          ValidationReport& report);

}  // namespace safecell
