#pragma once
// `safecell validate`: the whole sensing pipeline on random scenes of the simulated cell, checked
// against the exact collision ground truth (FCL). Per scene the robot stands at a random
// configuration, one or more humans and up to `max_objects` boxes (objects the cell file does not
// know: a crate left on the floor) at random places; the cameras render the scene, the pipeline
// makes the forbidden map, and many robot configurations (half of them turned towards a human or
// an object) are checked:
//   missed          colliding with a human or object that at least `camera_threshold` cameras
//                   saw (its feature cells are obstacles there after robot removal), or with a
//                   static obstacle, yet not forbidden. Must be 0.
//   unseen          colliding with a human or object fewer cameras saw (left to the other cameras
//                   and the camera threshold; reported, not a failure of the fusion).
//   false positive  forbidden but free.
// Phantom cells: critical cells sampled per scene whose robot (at the cell centre) stays farther
// than `phantom_distance_m` from every human and object, scaled up to the scene's critical cells.

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "safecell/cell/cell_model.hpp"
#include "safecell/fusion/forbidden_map_fusion.hpp"
#include "safecell/lut/lut_set.hpp"
#include "safecell/lut/robot_silhouettes.hpp"
#include "safecell/validation/scene_check.hpp"

namespace safecell {

struct ValidationOptions {
  std::size_t scenes = 200;
  std::uint64_t seed = 1;
  std::size_t configurations_per_scene = 400;
  int max_humans = 2;
  int max_objects = 1;  // boxes per scene: 0..max_objects
  std::size_t reference_frames = 9;
  std::size_t phantom_samples = 100;  // critical cells checked per scene
  double phantom_distance_m = 0.5;
  FusionSettings fusion;
};

// The checks of every scene added up (scene_check.hpp), and figures over the scenes.
struct ValidationReport : SceneCheck {
  std::size_t scenes = 0;
  std::size_t objects = 0;  // boxes placed, over all scenes
  double false_positive_rate = 0.0;
  double phantom_cells = 0.0;    // mean per scene (estimated from samples)
  double forbidden_share = 0.0;  // mean share of the grid forbidden per scene
  double fusion_ms_p99 = 0.0;
  double features_ms_p99 = 0.0;
};

// progress(scenes done, scenes). Throws std::invalid_argument for absurd options, or a cell
// without a robot model.
[[nodiscard]] ValidationReport validate_against_ground_truth(
    const CellModel& cell, const CspaceGrid& grid, const LutSet& luts,
    const RobotSilhouettes& silhouettes, const ValidationOptions& options,
    const std::function<void(std::size_t, std::size_t)>& progress = {});

}  // namespace safecell
