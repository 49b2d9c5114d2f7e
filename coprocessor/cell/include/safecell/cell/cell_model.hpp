#pragma once
// A cell with its robot loaded: every joint's range and lever arm l_i settled, from the robot
// model when the cell names one (l_i computed, ranges defaulting to the arm's limits) or from the
// cell file alone otherwise.

#include <optional>

#include "safecell/camera/feature_grid.hpp"
#include "safecell/camera/pinhole_camera.hpp"
#include "safecell/cell/cell_config.hpp"
#include "safecell/features/blocked_mask.hpp"
#include "safecell/robot/lever_arms.hpp"
#include "safecell/robot/robot_model.hpp"

namespace safecell {

struct CellModel {
  CellConfig config;  // complete: every joint has range_deg and l_m
  std::optional<RobotModel> robot;
  std::optional<LeverArms> lever_arms;
  std::vector<PinholeCamera> cameras;
  FeatureGrid feature_grid;
  std::vector<PlacedShape> obstacles;
  int camera_threshold = 1;  // settled: the cell's value or the default
  FeatureWeights feature_weights = kDefaultFeatureWeights;
  int blocked_threshold = kDefaultBlockedThreshold;
};

// The camera threshold of a cell that sets none: 3 of 4 or more cameras, 2 of 2 or 3, 1 of one.
// Three votes of four take out most phantoms two cameras agree on (validate, default cell, 200
// scenes: needless stops 49 % at 2, 8.8 % at 3, missed and unseen 0 at both) and still stand one
// camera failing or hidden from a person; with three cameras that would leave no slack.
[[nodiscard]] constexpr int default_camera_threshold(int cameras) {
  return cameras >= 4 ? 3 : (cameras >= 2 ? 2 : 1);
}

// Throws CellError naming the file, line and field: an unreadable robot, joints that do not match
// the robot's, a range outside the arm's limits, l_m given for a robot (it is computed), or range
// or l_m missing without one; unusable cameras, feature grid, obstacles, cell size or camera
// threshold.
CellModel load_cell_model(CellConfig config);

}  // namespace safecell
