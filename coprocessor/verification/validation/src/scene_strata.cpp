#include "safecell/validation/scene_strata.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <optional>
#include <stdexcept>

#include "safecell/robot/kinematics.hpp"
#include "safecell/sim/ground_truth.hpp"
#include "safecell/validation/configuration_strata.hpp"
#include "safecell/validation/scene_check.hpp"

namespace safecell {
namespace {

constexpr double kWallClearance_m = 0.3;
constexpr int kAttempts = 200;
constexpr int kConfigurationDraws = 8;   // robot configurations a stratum is tried at
constexpr double kAgainstStep_m = 0.02;  // how finely a person moves out until the arm is clear
constexpr int kAgainstSteps = 75;        // up to 1.5 m out

double uniform(std::mt19937_64& rng, double lo, double hi) {
  return std::uniform_real_distribution<double>(lo, hi)(rng);
}

double random_heading(std::mt19937_64& rng) {
  return uniform(rng, -std::numbers::pi, std::numbers::pi);
}

Eigen::Vector2d random_direction(std::mt19937_64& rng) {
  const double angle = random_heading(rng);
  return {std::cos(angle), std::sin(angle)};
}

// Placing bodies into one scene: where there is room for them.
class Placer {
 public:
  Placer(const CellModel& cell, SimScene& scene)
      : cell_(cell),
        scene_(scene),
        robot_(collision_shapes_at(*cell.robot, scene.q)),
        half_x_(cell.config.size_m[0] / 2.0 - kWallClearance_m),
        half_y_(cell.config.size_m[1] / 2.0 - kWallClearance_m) {}

  [[nodiscard]] double half_x() const { return half_x_; }
  [[nodiscard]] double half_y() const { return half_y_; }
  [[nodiscard]] const SimScene& scene() const { return scene_; }

  [[nodiscard]] Eigen::Vector2d random_floor_point(std::mt19937_64& rng) const {
    return {uniform(rng, -half_x_, half_x_), uniform(rng, -half_y_, half_y_)};
  }
  [[nodiscard]] bool inside(const Eigen::Vector2d& point) const {
    return std::abs(point.x()) <= half_x_ && std::abs(point.y()) <= half_y_;
  }
  [[nodiscard]] bool touches_robot(const std::vector<PlacedShape>& body) const {
    return GroundTruth(body).collides(robot_);
  }
  // Room for `body`: not in the robot, a static obstacle or a body placed before.
  [[nodiscard]] bool has_room(const std::vector<PlacedShape>& body) const {
    if (touches_robot(body)) return false;
    std::vector<PlacedShape> occupied = cell_.obstacles;
    for (auto& shape : moving_bodies(scene_)) occupied.push_back(std::move(shape));
    return occupied.empty() || !GroundTruth(occupied).collides(body);
  }
  bool try_human(const HumanPose& pose) {
    if (!inside(pose.position_m) || !has_room(human_shapes(pose))) return false;
    scene_.humans.push_back(pose);
    return true;
  }
  bool try_object(const PlacedShape& object) {
    if (!inside(object.pose.translation().head<2>()) || !has_room({object})) return false;
    scene_.objects.push_back(object);
    return true;
  }

 private:
  const CellModel& cell_;
  SimScene& scene_;
  std::vector<PlacedShape> robot_;
  double half_x_;
  double half_y_;
};

HumanPose standing_at(const Eigen::Vector2d& position, double heading_rad, std::mt19937_64& rng) {
  HumanPose pose;
  pose.position_m = position;
  pose.heading_rad = heading_rad;
  pose.gait_phase_rad = uniform(rng, 0.0, 2.0 * std::numbers::pi);
  pose.arm_raise_rad = uniform(rng, 0.0, 1.2);
  return pose;
}

double heading_towards(const Eigen::Vector2d& from, const Eigen::Vector2d& to) {
  const Eigen::Vector2d step = to - from;
  return std::atan2(step.y(), step.x());
}

// A box 0.2-0.8 m a side and 0.2-1.2 m high standing on the floor at a random place, turned.
PlacedShape floor_box(const Eigen::Vector2d& at, std::mt19937_64& rng) {
  const Eigen::Vector3d size(uniform(rng, 0.2, 0.8), uniform(rng, 0.2, 0.8),
                             uniform(rng, 0.2, 1.2));
  PlacedShape object{Box{size}, Eigen::Isometry3d::Identity()};
  object.pose.translate(Eigen::Vector3d(at.x(), at.y(), size.z() / 2.0));
  object.pose.rotate(Eigen::AngleAxisd(random_heading(rng), Eigen::Vector3d::UnitZ()));
  return object;
}

// A box 0.1-0.4 m a side standing on top of a static obstacle (a part on the workbench).
std::optional<PlacedShape> box_on(const PlacedShape& obstacle, std::mt19937_64& rng) {
  const auto* table = std::get_if<Box>(&obstacle.shape);
  if (table == nullptr) return std::nullopt;
  const Eigen::Vector3d size(uniform(rng, 0.1, 0.4), uniform(rng, 0.1, 0.4),
                             uniform(rng, 0.1, 0.4));
  const Eigen::Vector3d local(uniform(rng, -0.5, 0.5) * table->size_m.x(),
                              uniform(rng, -0.5, 0.5) * table->size_m.y(),
                              table->size_m.z() / 2.0 + size.z() / 2.0 + 1e-3);
  PlacedShape object{Box{size}, obstacle.pose};
  object.pose.translate(local);
  object.pose.rotate(Eigen::AngleAxisd(random_heading(rng), Eigen::Vector3d::UnitZ()));
  return object;
}

// A point on the arm at the scene's configuration: on the segment between the origins of two
// consecutive links past the first (the column of the base is not "the arm").
Eigen::Vector3d arm_point(const CellModel& cell, const std::vector<double>& q,
                          std::mt19937_64& rng) {
  const std::vector<Eigen::Isometry3d> poses = link_poses(*cell.robot, q);
  if (poses.size() < 3) return poses.back().translation();
  const std::size_t link = std::uniform_int_distribution<std::size_t>(1, poses.size() - 2)(rng);
  const double t = uniform(rng, 0.0, 1.0);
  return (1.0 - t) * poses[link].translation() + t * poses[link + 1].translation();
}

Eigen::Vector2d camera_floor_point(const CellModel& cell, std::mt19937_64& rng) {
  const std::size_t c = std::uniform_int_distribution<std::size_t>(0, cell.cameras.size() - 1)(rng);
  return cell.cameras[c].position_m().head<2>();
}

void place_uniform(Placer& placer, const SceneLimits& limits, std::mt19937_64& rng) {
  const int humans = std::uniform_int_distribution<int>(1, limits.max_humans)(rng);
  for (int attempt = 0;
       attempt < kAttempts && static_cast<int>(placer.scene().humans.size()) < humans; ++attempt) {
    (void)placer.try_human(standing_at(placer.random_floor_point(rng), random_heading(rng), rng));
  }
  const int objects = std::uniform_int_distribution<int>(0, limits.max_objects)(rng);
  for (int attempt = 0;
       attempt < kAttempts && static_cast<int>(placer.scene().objects.size()) < objects;
       ++attempt) {
    (void)placer.try_object(floor_box(placer.random_floor_point(rng), rng));
  }
}

bool place_against_arm(Placer& placer, const CellModel& cell, std::mt19937_64& rng) {
  for (int attempt = 0; attempt < kAttempts; ++attempt) {
    const Eigen::Vector2d point = arm_point(cell, placer.scene().q, rng).head<2>();
    const Eigen::Vector2d away = random_direction(rng);
    HumanPose pose = standing_at(point, heading_towards(away, Eigen::Vector2d::Zero()), rng);
    // Out from the arm until the person no longer touches it: then they stand against it.
    for (int step = 0; step < kAgainstSteps; ++step) {
      pose.position_m = point + kAgainstStep_m * step * away;
      if (placer.touches_robot(human_shapes(pose))) continue;
      if (step > 0 && placer.try_human(pose)) return true;
      break;
    }
  }
  return false;
}

bool place_behind_arm(Placer& placer, const CellModel& cell, std::mt19937_64& rng) {
  for (int attempt = 0; attempt < kAttempts; ++attempt) {
    const Eigen::Vector2d point = arm_point(cell, placer.scene().q, rng).head<2>();
    const Eigen::Vector2d from_camera = point - camera_floor_point(cell, rng);
    if (from_camera.norm() < 1e-6) continue;
    const Eigen::Vector2d at = point + uniform(rng, 0.3, 1.2) * from_camera.normalized();
    if (placer.try_human(standing_at(at, random_heading(rng), rng))) return true;
  }
  return false;
}

bool place_reaching(Placer& placer, const CellModel& cell, std::mt19937_64& rng) {
  for (int attempt = 0; attempt < kAttempts; ++attempt) {
    const Eigen::Vector2d point = arm_point(cell, placer.scene().q, rng).head<2>();
    const Eigen::Vector2d at = point + uniform(rng, 0.4, 1.0) * random_direction(rng);
    HumanPose pose = standing_at(at, heading_towards(at, point), rng);
    pose.gait_amplitude = 0.0;
    pose.right_arm_reach_rad = uniform(rng, 0.9, 1.8);
    if (placer.try_human(pose)) return true;
  }
  return false;
}

bool place_behind_static_obstacle(Placer& placer, const CellModel& cell, std::mt19937_64& rng) {
  if (cell.obstacles.empty()) return false;
  for (int attempt = 0; attempt < kAttempts; ++attempt) {
    const auto b = std::uniform_int_distribution<std::size_t>(0, cell.obstacles.size() - 1)(rng);
    const Eigen::Vector2d centre = cell.obstacles[b].pose.translation().head<2>();
    const Eigen::Vector2d from_camera = centre - camera_floor_point(cell, rng);
    if (from_camera.norm() < 1e-6) continue;
    const Eigen::Vector2d at = centre + uniform(rng, 0.4, 1.0) * from_camera.normalized();
    if (placer.try_human(standing_at(at, random_heading(rng), rng))) return true;
  }
  return false;
}

bool place_boxes(Placer& placer, const CellModel& cell, const SceneLimits& limits,
                 std::mt19937_64& rng) {
  const int boxes = std::uniform_int_distribution<int>(1, std::max(1, limits.max_objects) + 1)(rng);
  for (int attempt = 0;
       attempt < kAttempts && static_cast<int>(placer.scene().objects.size()) < boxes; ++attempt) {
    const bool on_obstacle = !cell.obstacles.empty() && attempt % 2 == 0;
    if (on_obstacle) {
      const auto b = std::uniform_int_distribution<std::size_t>(0, cell.obstacles.size() - 1)(rng);
      if (const auto box = box_on(cell.obstacles[b], rng)) (void)placer.try_object(*box);
    } else {
      (void)placer.try_object(floor_box(placer.random_floor_point(rng), rng));
    }
  }
  return !placer.scene().objects.empty();
}

bool place_stratum(SceneStratum stratum, Placer& placer, const CellModel& cell,
                   const SceneLimits& limits, std::mt19937_64& rng) {
  switch (stratum) {
    case SceneStratum::kUniform:
      return false;
    case SceneStratum::kAgainstArm:
      return place_against_arm(placer, cell, rng);
    case SceneStratum::kBehindArm:
      return place_behind_arm(placer, cell, rng);
    case SceneStratum::kReaching:
      return place_reaching(placer, cell, rng);
    case SceneStratum::kBehindStaticObstacle:
      return place_behind_static_obstacle(placer, cell, rng);
    case SceneStratum::kBoxes:
      return place_boxes(placer, cell, limits, rng);
  }
  return false;
}

}  // namespace

const char* to_string(SceneStratum stratum) {
  switch (stratum) {
    case SceneStratum::kUniform:
      return "uniform";
    case SceneStratum::kAgainstArm:
      return "against_arm";
    case SceneStratum::kBehindArm:
      return "behind_arm";
    case SceneStratum::kReaching:
      return "reaching";
    case SceneStratum::kBehindStaticObstacle:
      return "behind_static_obstacle";
    case SceneStratum::kBoxes:
      return "boxes";
  }
  return "unknown";
}

StratifiedScene make_scene(SceneStratum stratum, const CellModel& cell, const CspaceGrid& grid,
                           const SceneLimits& limits, std::mt19937_64& rng) {
  if (!cell.robot) throw std::invalid_argument("validation scenes need a cell with a robot model");
  StratifiedScene placed;
  placed.stratum = stratum;
  // The arm at one configuration can fill the only room a stratum has (behind the workbench, as
  // the one camera that can see it there looks): then the stratum is tried at another.
  for (int draw = 0; draw < kConfigurationDraws && stratum != SceneStratum::kUniform; ++draw) {
    placed.scene = SimScene{};
    placed.scene.q = random_configuration(grid, rng);
    Placer placer(cell, placed.scene);
    if (place_stratum(stratum, placer, cell, limits, rng)) return placed;
  }
  placed.scene = SimScene{};
  placed.scene.q = random_configuration(grid, rng);
  placed.stratum = SceneStratum::kUniform;
  Placer placer(cell, placed.scene);
  place_uniform(placer, limits, rng);
  return placed;
}

}  // namespace safecell
