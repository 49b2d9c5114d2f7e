#pragma once
// `safecell validate`: the whole sensing pipeline on random scenes of the simulated cell, checked
// against the exact ground truth (FCL for collisions, the renderer's object-id images for what
// each camera sees), in the terms of ../shared/VALIDATION.md (scene_check.hpp). Scene s is of
// stratum s mod 6 (scene_strata.hpp), its configurations of the three configuration strata in
// turn (configuration_strata.hpp); each scene draws from its own generator, seeded with the run's
// seed and s, so that a scene is the same whichever thread, shard or run takes it.
//
// With model error, the simulated world (cameras, robot) differs from the model the tables and
// the pipeline use (model_error.hpp); the ground truth is the world's.
//
// Scenes run in parallel, one simulated cell and pipeline per thread. A run may be one shard of
// many (`shard` K of N takes the K-th of N contiguous parts of the scenes); the reports of all
// shards add up to the report of the whole run (operator+=), timings aside.

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "safecell/cell/cell_model.hpp"
#include "safecell/fusion/forbidden_map_fusion.hpp"
#include "safecell/silhouettes/robot_silhouettes.hpp"
#include "safecell/tables/lut_set.hpp"
#include "safecell/validation/model_error.hpp"
#include "safecell/validation/negative_controls.hpp"
#include "safecell/validation/scene_check.hpp"
#include "safecell/validation/scene_strata.hpp"
#include "safecell/validation/separation_check.hpp"

namespace safecell {

struct Shard {
  std::size_t index = 1;  // 1..count
  std::size_t count = 1;
};

struct ValidationOptions {
  std::size_t scenes = 200;  // in the whole run, over all shards
  std::uint64_t seed = 1;
  std::size_t configurations_per_scene = 400;
  SceneLimits limits;
  std::size_t reference_frames = 9;
  FusionSettings fusion;
  unsigned threads = 0;  // 0: one per hardware thread
  Shard shard;
  NegativeControl negative_control = NegativeControl::kNone;
  ModelError model_error;  // applied to the simulated world, not to the model
  std::size_t needless_stops_traced_per_scene = 2;  // scene_check.hpp, "clear"
};

// The scenes [first, end) that shard `shard` of a run of `scenes` takes.
struct SceneRange {
  std::size_t first = 0;
  std::size_t end = 0;
};
[[nodiscard]] SceneRange scenes_of_shard(std::size_t scenes, const Shard& shard);

// The checks of every scene added up, and figures over the scenes. Everything but the timings
// adds exactly over shards.
struct ValidationReport : SceneCheck {
  std::size_t scenes = 0;
  std::size_t objects = 0;           // boxes placed, over all scenes
  double forbidden_share_sum = 0.0;  // the grid's forbidden share, summed over the scenes
  std::map<std::string, std::size_t> scenes_per_stratum;
  SeparationFigures separation;  // the protective separation check (none when the cell has none)
  double fusion_ms_p99 = 0.0;    // a merge keeps the largest
  double features_ms_p99 = 0.0;  // a merge keeps the largest

  ValidationReport& operator+=(const ValidationReport& other);
  [[nodiscard]] double forbidden_share() const {
    return scenes == 0 ? 0.0 : forbidden_share_sum / static_cast<double>(scenes);
  }
};

// progress(scenes done, scenes of the shard), from any thread but never from two at once.
// Throws std::invalid_argument for absurd options, or a cell without a robot model.
[[nodiscard]] ValidationReport validate_against_ground_truth(
    const CellModel& cell, const CspaceGrid& grid, const LutSet& luts,
    const RobotSilhouettes& silhouettes, const ValidationOptions& options,
    const std::function<void(std::size_t, std::size_t)>& progress = {});

}  // namespace safecell
