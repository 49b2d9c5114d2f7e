#include "safecell/cell/cell_model.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>

#include "safecell/cell/cell_error.hpp"
#include "safecell/cell/cell_scene.hpp"
#include "safecell/robot/default_robot.hpp"
#include "safecell/robot/robot_error.hpp"
#include "safecell/robot/urdf_loader.hpp"

namespace safecell {
namespace {

constexpr double kDegPerRad = 180.0 / std::numbers::pi;
// Degrees are rounded in files; a range may exceed the arm's limit by this much.
constexpr double kRangeTolerance_deg = 1e-6;

std::string joint_path(std::size_t j) { return "joints[" + std::to_string(j) + "]"; }

RobotModel load_robot(const RobotConfig& robot) {
  const std::string builtin = std::string(kBuiltinRobotPrefix) + "rx130_class";
  try {
    if (robot.urdf.rfind(kBuiltinRobotPrefix, 0) == 0) {
      if (robot.urdf != builtin) {
        throw_cell_error(robot.at, "robot.urdf",
                         "unknown built-in robot '" + robot.urdf + "' (expected " + builtin + ")");
      }
      if (!robot.collision_stand_ins.empty()) {
        throw_cell_error(robot.at, "robot.collision_stand_ins",
                         "given, but the built-in arm has collision geometry on every link");
      }
      RobotModel model = default_robot();
      if (!robot.tool_link.empty() && !model.frame(robot.tool_link)) {
        throw_cell_error(robot.at, "robot.tool_link",
                         "the built-in arm has no link '" + robot.tool_link + "'");
      }
      return model;
    }
    return load_urdf_file(robot.urdf, UrdfOptions{robot.tool_link, robot.collision_stand_ins});
  } catch (const RobotError& error) {
    throw_cell_error(robot.at, "robot.urdf", error.what());
  }
}

void settle_from_robot(CellModel& model) {
  CellConfig& cell = model.config;
  const RobotModel& robot = *model.robot;
  if (cell.joints.size() != robot.dof()) {
    std::string names;
    for (const auto& joint : robot.joints) names += (names.empty() ? "" : ", ") + joint.name;
    throw_cell_error(cell.joints_at, "joints",
                     std::to_string(cell.joints.size()) + " joints listed, but robot '" +
                         robot.name + "' has " + std::to_string(robot.dof()) + " movable joints (" +
                         names + ")");
  }
  const RobotConfig& robot_config = *cell.robot;
  const ToolSpec tool{robot_config.tool_frame, robot_config.tool_shapes,
                      Eigen::Vector3d(robot_config.tool_point_m[0], robot_config.tool_point_m[1],
                                      robot_config.tool_point_m[2])};
  try {
    attach_tool(*model.robot, tool);
    model.lever_arms = compute_lever_arms(*model.robot, tool);
  } catch (const RobotError& error) {
    throw_cell_error(robot_config.at, "robot.tool", error.what());
  }
  for (std::size_t j = 0; j < robot.dof(); ++j) {
    JointConfig& joint = cell.joints[j];
    const RobotJoint& arm = robot.joints[j];
    if (joint.name != arm.name) {
      throw_cell_error(joint.at, joint_path(j) + ".name",
                       "'" + joint.name + "' is not the robot's joint " + std::to_string(j + 1) +
                           " '" + arm.name + "' (list the joints in chain order)");
    }
    if (joint.l_m) {
      throw_cell_error(joint.l_at, joint_path(j) + ".l_m",
                       "given, but l_i is computed from the robot model; remove it");
    }
    joint.l_m = model.lever_arms->envelope_m[j];
    joint.l_at = joint.at;  // an error about it names the joint's line: it has none of its own
    const std::array<double, 2> limits{arm.lower * kDegPerRad, arm.upper * kDegPerRad};
    if (!joint.range_deg) {
      joint.range_deg = limits;
      joint.range_at = joint.at;
    } else if ((*joint.range_deg)[0] < limits[0] - kRangeTolerance_deg ||
               (*joint.range_deg)[1] > limits[1] + kRangeTolerance_deg) {
      throw_cell_error(joint.range_at, joint_path(j) + ".range_deg",
                       "value [" + std::to_string((*joint.range_deg)[0]) + ", " +
                           std::to_string((*joint.range_deg)[1]) +
                           "] lies outside the arm's limits [" + std::to_string(limits[0]) + ", " +
                           std::to_string(limits[1]) + "]");
    }
  }
}

void settle_blocked_cells(CellModel& model) {
  const BlockedCellConfig& blocked = model.config.blocked_cells;
  if (blocked.weights) {
    const auto& w = *blocked.weights;
    model.feature_weights = FeatureWeights{w[0], w[1], w[2], w[3], w[4]};
    const bool in_range = std::all_of(
        w.begin(), w.end(), [](int weight) { return weight >= 0 && weight <= kMaxFeatureWeight; });
    if (!in_range || std::all_of(w.begin(), w.end(), [](int weight) { return weight == 0; })) {
      throw_cell_error(blocked.at, "blocked_cells.weights",
                       "expected whole numbers 0 to " + std::to_string(kMaxFeatureWeight) +
                           ", at least one above 0");
    }
  }
  if (blocked.threshold) {
    model.blocked_threshold = *blocked.threshold;
    if (model.blocked_threshold < 0) {
      throw_cell_error(blocked.at, "blocked_cells.threshold",
                       "value " + std::to_string(model.blocked_threshold) + ", expected 0 or more");
    }
  }
}

void settle_envelope_subdivision(CellModel& model) {
  const CellConfig& cell = model.config;
  if (!cell.envelope_max_move_m) return;
  const double max_move = *cell.envelope_max_move_m;
  if (!std::isfinite(max_move) || !(max_move > 0.0)) {
    throw_cell_error(cell.envelope_max_move_at, "envelope_max_move_m",
                     "value " + std::to_string(max_move) + ", expected a distance above 0 m");
  }
  // Sub-cells only tighten the silhouettes (every count is sound), so a max-move below
  // m_max_m / kMaxEnvelopeSubdivision (a cell file whose m_max_m a tool or test raised) takes the
  // most sub-cells there are. The relative slack keeps m_max_m / 2 written in decimals at 2.
  const double parts = std::ceil(cell.m_max_m / max_move * (1.0 - 1e-9));
  model.envelope_subdivision = static_cast<std::uint32_t>(
      std::clamp(parts, 1.0, static_cast<double>(kMaxEnvelopeSubdivision)));
}

void settle_balls_and_parts(CellModel& model) {
  const CellConfig& cell = model.config;
  if (cell.ball_radius_m) {
    const double radius = *cell.ball_radius_m;
    if (!is_ball_radius(radius)) {
      throw_cell_error(cell.ball_radius_at, "ball_radius_m",
                       "value " + std::to_string(radius) + ", expected " + ball_radius_range());
    }
    model.ball_radius_m = radius;
  }
  if (!cell.robot_parts) return;
  if (!parse_part_split(*cell.robot_parts, model.robot_parts)) {
    throw_cell_error(cell.robot_parts_at, "robot_parts",
                     "value '" + *cell.robot_parts + "', expected " + part_split_names());
  }
}

void settle_scene(CellModel& model) {
  const CellConfig& cell = model.config;
  for (const double size : cell.size_m) {
    if (!(std::isfinite(size) && size > 0.0)) {
      throw_cell_error(cell.size_at, "size_m",
                       "value " + std::to_string(size) + ", expected inside dimensions above 0 m");
    }
  }
  settle_blocked_cells(model);
  model.cameras = cell_cameras(cell);
  model.feature_grid = cell_feature_grid(cell, model.cameras);
  model.obstacles = cell_obstacles(cell);
  const int cameras = static_cast<int>(model.cameras.size());
  model.camera_threshold = cell.camera_threshold.value_or(std::min(2, std::max(1, cameras)));
  if (model.camera_threshold < 1 || (cameras > 0 && model.camera_threshold > cameras)) {
    throw_cell_error(cell.camera_threshold_at, "camera_threshold",
                     "value " + std::to_string(model.camera_threshold) +
                         ", expected 1 to the number of cameras (" + std::to_string(cameras) + ")");
  }
  if (cell.occlusion_reach_cells) {
    // Past the longer side of the feature grid a blob has nowhere further to grow.
    const int longest = std::max(model.feature_grid.columns(), model.feature_grid.rows());
    const int reach = *cell.occlusion_reach_cells;
    if (reach < 0 || reach > longest) {
      throw_cell_error(cell.occlusion_reach_at, "occlusion_reach_cells",
                       "value " + std::to_string(reach) + ", expected 0 to " +
                           std::to_string(longest) +
                           " feature cells (the feature grid's longer side)");
    }
    model.occlusion_reach_cells = reach;
  }
  settle_envelope_subdivision(model);
  settle_balls_and_parts(model);
}

void settle_joints_without_robot(const CellConfig& cell) {
  for (std::size_t j = 0; j < cell.joints.size(); ++j) {
    const JointConfig& joint = cell.joints[j];
    if (!joint.range_deg) {
      throw_cell_error(joint.at, joint_path(j) + ".range_deg",
                       "missing (required without a robot)");
    }
    if (!joint.l_m) {
      throw_cell_error(joint.at, joint_path(j) + ".l_m", "missing (required without a robot)");
    }
  }
}

}  // namespace

std::string ball_radius_range() {
  char text[64];
  std::snprintf(text, sizeof text, "%g to %g m", kMinBallRadius_m, kMaxBallRadius_m);
  return text;
}

CellModel load_cell_model(CellConfig config) {
  CellModel model{std::move(config),
                  std::nullopt,
                  std::nullopt,
                  {},
                  {},
                  {},
                  1,
                  std::nullopt,
                  1,
                  kDefaultFeatureWeights,
                  kDefaultBlockedThreshold,
                  PartSplit::kArmSegments,
                  kDefaultBallRadius_m};
  if (model.config.robot) {
    model.robot = load_robot(*model.config.robot);
    settle_from_robot(model);
  } else {
    settle_joints_without_robot(model.config);
  }
  settle_scene(model);
  return model;
}

}  // namespace safecell
