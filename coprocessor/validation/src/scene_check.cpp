#include "safecell/validation/scene_check.hpp"

#include <algorithm>
#include <cmath>

#include "safecell/robot/kinematics.hpp"
#include "safecell/sim/ground_truth.hpp"

namespace safecell {
namespace {

constexpr std::size_t kMissedCasesKept = 10;

// The feature cells a mask of pixels touches.
FeatureMask feature_cells_of(const cv::Mat& pixels, const FeatureGrid& grid) {
  FeatureMask cells(grid);
  for (int y = 0; y < pixels.rows; ++y) {
    const auto* row = pixels.ptr<std::uint8_t>(y);
    for (int x = 0; x < pixels.cols; ++x) {
      if (row[x] != 0) cells.set(x / grid.cell_width_px(), y / grid.cell_height_px());
    }
  }
  return cells;
}

CellIndex cell_of(const CspaceGrid& grid, const std::vector<double>& q) {
  JointAngles angles;
  for (std::size_t j = 0; j < q.size(); ++j) angles.rad[j] = q[j];
  return grid.cell_containing(angles).value();
}

}  // namespace

std::vector<PlacedShape> moving_bodies(const SimScene& scene) {
  std::vector<PlacedShape> bodies = scene.objects;
  for (const auto& human : scene.humans) {
    for (auto& part : human_shapes(human)) bodies.push_back(std::move(part));
  }
  return bodies;
}

std::vector<double> random_configuration(const CspaceGrid& grid, std::mt19937_64& rng) {
  std::vector<double> q(grid.joint_count());
  for (std::uint32_t j = 0; j < grid.joint_count(); ++j) {
    q[j] = std::uniform_real_distribution<double>(grid.joint(j).lo_rad, grid.joint(j).hi_rad)(rng);
  }
  return q;
}

SceneCheck& SceneCheck::operator+=(const SceneCheck& other) {
  configs_checked += other.configs_checked;
  colliding += other.colliding;
  missed += other.missed;
  unseen += other.unseen;
  free += other.free;
  false_positives += other.false_positives;
  for (const auto& missed_case : other.missed_cases) {
    if (missed_cases.size() < kMissedCasesKept) missed_cases.push_back(missed_case);
  }
  return *this;
}

SceneCheck check_scene(const CellModel& cell, const CspaceGrid& grid, SimulatedCell& sim,
                       const SensingPipeline& pipeline, const SimScene& scene,
                       std::size_t configurations, std::mt19937_64& rng, std::size_t scene_index) {
  SceneCheck check;
  // The scene's moving obstacles (humans, then objects) and how many cameras saw each: its
  // feature cells are obstacles there after robot removal.
  const std::size_t humans = scene.humans.size();
  const std::size_t movers = humans + scene.objects.size();
  check.cameras_seeing.assign(movers, 0);
  std::vector<PlacedShape> obstacles;
  std::vector<std::string> obstacle_names;
  std::vector<int> obstacle_mover;  // -1: a static obstacle of the cell file
  for (std::size_t m = 0; m < movers; ++m) {
    SimScene alone{scene.q, {}, {}};
    if (m < humans) {
      alone.humans.push_back(scene.humans[m]);
    } else {
      alone.objects.push_back(scene.objects[m - humans]);
    }
    auto surfaces = sim.moving_surfaces(alone);
    surfaces.erase(surfaces.begin());  // the robot
    for (std::size_t c = 0; c < sim.camera_count(); ++c) {
      const FeatureMask seen = feature_cells_of(sim.coverage(c, surfaces), cell.feature_grid);
      if (pipeline.observations()[c].known && seen.intersects(pipeline.fusion().obstacles(c))) {
        ++check.cameras_seeing[m];
      }
    }
    const std::string name =
        m < humans ? "human " + std::to_string(m + 1) : "object " + std::to_string(m - humans + 1);
    for (auto& part : m < humans ? human_shapes(scene.humans[m]) : alone.objects) {
      obstacles.push_back(std::move(part));
      obstacle_names.push_back(name);
      obstacle_mover.push_back(static_cast<int>(m));
    }
  }
  for (std::size_t b = 0; b < cell.obstacles.size(); ++b) {
    obstacles.push_back(cell.obstacles[b]);
    obstacle_names.push_back(cell.config.obstacles.at(b).name);
    obstacle_mover.push_back(-1);
  }
  std::vector<Eigen::Vector2d> targets;
  for (const auto& human : scene.humans) targets.push_back(human.position_m);
  for (const auto& object : scene.objects) targets.push_back(object.pose.translation().head<2>());
  if (obstacles.empty()) return check;
  const GroundTruth truth(obstacles);
  const CellSet& forbidden = pipeline.fusion().forbidden();
  const int threshold = pipeline.fusion().settings().camera_threshold;

  for (std::size_t k = 0; k < configurations; ++k) {
    std::vector<double> q = random_configuration(grid, rng);
    if (k % 2 == 1 && !targets.empty()) {  // turned towards a human or an object
      const auto& target = targets[k / 2 % targets.size()];
      q[0] = std::clamp(std::atan2(target.y(), target.x()) +
                            std::uniform_real_distribution<double>(-0.3, 0.3)(rng),
                        grid.joint(0).lo_rad, grid.joint(0).hi_rad);
    }
    const bool is_forbidden = forbidden.test(cell_of(grid, q));
    const auto hit = truth.first_colliding_obstacle(collision_shapes_at(*cell.robot, q));
    ++check.configs_checked;
    if (!hit) {
      ++check.free;
      check.false_positives += is_forbidden ? 1 : 0;
      continue;
    }
    ++check.colliding;
    const int mover = obstacle_mover[*hit];
    const int seeing = mover < 0 ? static_cast<int>(sim.camera_count())
                                 : check.cameras_seeing[static_cast<std::size_t>(mover)];
    if (mover >= 0 && seeing < threshold) {
      ++check.unseen;
      continue;
    }
    if (!is_forbidden) {
      ++check.missed;
      if (check.missed_cases.size() < kMissedCasesKept) {
        check.missed_cases.push_back(MissedCollision{scene_index, q, obstacle_names[*hit], seeing});
      }
    }
  }
  return check;
}

double estimate_phantom_cells(const CellModel& cell, const CspaceGrid& grid,
                              const SensingPipeline& pipeline,
                              const std::vector<PlacedShape>& bodies, std::size_t samples,
                              double distance_m, std::mt19937_64& rng) {
  const CellSet& critical = pipeline.fusion().critical();
  std::vector<CellIndex> critical_cells;
  for (CellIndex c = critical.next_set(0); c < critical.cell_count();
       c = critical.next_set(c + 1)) {
    critical_cells.push_back(c);
  }
  if (critical_cells.empty() || bodies.empty() || samples == 0) return 0.0;
  const GroundTruth truth(bodies);
  std::size_t phantoms = 0;
  const std::size_t checked = std::min(samples, critical_cells.size());
  std::uniform_int_distribution<std::size_t> pick(0, critical_cells.size() - 1);
  for (std::size_t i = 0; i < checked; ++i) {
    const JointAngles centre =
        grid.cell_centre(grid.coords_of(critical_cells[pick(rng)]).value()).value();
    const std::vector<double> q(centre.rad, centre.rad + grid.joint_count());
    if (truth.min_distance_m(collision_shapes_at(*cell.robot, q)) > distance_m) ++phantoms;
  }
  return static_cast<double>(phantoms) / static_cast<double>(checked) *
         static_cast<double>(critical_cells.size());
}

}  // namespace safecell
