#pragma once
// A cell with its robot loaded: every joint's range and lever arm l_i settled, from the robot
// model when the cell names one (l_i computed, ranges defaulting to the arm's limits) or from the
// cell file alone otherwise.

#include <cstdint>
#include <optional>
#include <string>

#include "safecell/camera/feature_grid.hpp"
#include "safecell/camera/pinhole_camera.hpp"
#include "safecell/cell/cell_config.hpp"
#include "safecell/features/blocked_mask.hpp"
#include "safecell/robot/lever_arms.hpp"
#include "safecell/robot/robot_model.hpp"
#include "safecell/robot/robot_parts.hpp"

namespace safecell {

// Sub-cells per joint: more would multiply the table build's work by more than 4^d (256 with the
// default cell's 4 discretised joints).
inline constexpr std::uint32_t kMaxEnvelopeSubdivision = 4;

// The balls' size of a cell file that does not say (ball_radius_m), and the sizes it may say:
// smaller balls take a quarter of their size as the sampling step over every surface.
inline constexpr double kDefaultBallRadius_m = 0.06;
inline constexpr double kMinBallRadius_m = 0.005;
inline constexpr double kMaxBallRadius_m = 0.5;
// Whether radius_m lies within those sizes (false for NaN).
[[nodiscard]] constexpr bool is_ball_radius(double radius_m) {
  return radius_m >= kMinBallRadius_m && radius_m <= kMaxBallRadius_m;
}
// Those sizes for messages: "0.005 to 0.5 m".
[[nodiscard]] std::string ball_radius_range();

struct CellModel {
  CellConfig config;  // complete: every joint has range_deg and l_m
  std::optional<RobotModel> robot;
  std::optional<LeverArms> lever_arms;
  std::vector<PinholeCamera> cameras;
  FeatureGrid feature_grid;
  std::vector<PlacedShape> obstacles;
  int camera_threshold = 1;  // settled: the cell's value or the default
  // Feature cells, checked against the feature grid; unset: the fusion's default.
  std::optional<int> occlusion_reach_cells;
  // Sub-cells per discretised joint of a cell's envelope (1 to kMaxEnvelopeSubdivision), settled
  // from envelope_max_move_m: the model-mode tables' silhouettes are the union of theirs.
  std::uint32_t envelope_subdivision = 1;
  FeatureWeights feature_weights = kDefaultFeatureWeights;
  int blocked_threshold = kDefaultBlockedThreshold;
  // The robot parts the cameras vote on, settled from robot_parts: the model-mode tables hold
  // one LUT-2 per part and camera.
  PartSplit robot_parts = PartSplit::kArmSegments;
  // The size of the balls covering the robot, settled from ball_radius_m.
  double ball_radius_m = kDefaultBallRadius_m;
};

// Throws CellError naming the file, line and field: an unreadable robot, joints that do not match
// the robot's, a range outside the arm's limits, l_m given for a robot (it is computed), or range
// or l_m missing without one; unusable cameras, feature grid, obstacles, cell size, camera
// threshold, occlusion reach, envelope max-move, ball radius or robot parts.
CellModel load_cell_model(CellConfig config);

}  // namespace safecell
