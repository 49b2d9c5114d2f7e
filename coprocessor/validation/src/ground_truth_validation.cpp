#include "safecell/validation/ground_truth_validation.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>
#include <stdexcept>

#include "safecell/pipeline/sensing_pipeline.hpp"
#include "safecell/pipeline/simulated_reference.hpp"
#include "safecell/robot/kinematics.hpp"
#include "safecell/sim/cell_simulation.hpp"
#include "safecell/sim/ground_truth.hpp"

namespace safecell {
namespace {

constexpr std::size_t kMissedCasesKept = 10;
constexpr double kWallClearance_m = 0.3;

double percentile(std::vector<double> values, double share) {
  if (values.empty()) return 0.0;
  std::sort(values.begin(), values.end());
  const auto index = static_cast<std::size_t>(std::ceil(share * static_cast<double>(values.size()))) - 1;
  return values[std::min(index, values.size() - 1)];
}

std::vector<double> random_q(const CspaceGrid& grid, std::mt19937_64& rng) {
  std::vector<double> q(grid.joint_count());
  for (std::uint32_t j = 0; j < grid.joint_count(); ++j) {
    q[j] = std::uniform_real_distribution<double>(grid.joint(j).lo_rad, grid.joint(j).hi_rad)(rng);
  }
  return q;
}

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

struct Scene {
  std::vector<double> q;
  std::vector<HumanPose> humans;
};

Scene random_scene(const CellModel& cell, const CspaceGrid& grid, std::mt19937_64& rng,
                   int max_humans) {
  Scene scene;
  scene.q = random_q(grid, rng);
  const auto robot = collision_shapes_at(*cell.robot, scene.q);
  const double half_x = cell.config.size_m[0] / 2.0 - kWallClearance_m;
  const double half_y = cell.config.size_m[1] / 2.0 - kWallClearance_m;
  const int humans = std::uniform_int_distribution<int>(1, max_humans)(rng);
  for (int attempt = 0; attempt < 200 && static_cast<int>(scene.humans.size()) < humans; ++attempt) {
    HumanPose pose;
    pose.position_m = {std::uniform_real_distribution<double>(-half_x, half_x)(rng),
                       std::uniform_real_distribution<double>(-half_y, half_y)(rng)};
    pose.heading_rad = std::uniform_real_distribution<double>(-std::numbers::pi, std::numbers::pi)(rng);
    pose.gait_phase_rad = std::uniform_real_distribution<double>(0.0, 2.0 * std::numbers::pi)(rng);
    pose.arm_raise_rad = std::uniform_real_distribution<double>(0.0, 1.2)(rng);
    const auto body = human_shapes(pose);
    // Humans stand where there is room: not inside the robot, a box or another human.
    std::vector<PlacedShape> occupied = cell.obstacles;
    for (const auto& other : scene.humans) {
      for (auto& part : human_shapes(other)) occupied.push_back(std::move(part));
    }
    if (GroundTruth(body).collides(robot)) continue;
    if (!occupied.empty() && GroundTruth(occupied).collides(body)) continue;
    scene.humans.push_back(pose);
  }
  return scene;
}

void check_options(const CellModel& cell, const ValidationOptions& options) {
  if (!cell.robot) throw std::invalid_argument("validation needs a cell with a robot model");
  if (options.scenes == 0 || options.configurations_per_scene == 0) {
    throw std::invalid_argument("validation needs at least one scene and one configuration");
  }
  if (options.max_humans < 1 || options.max_humans > 10) {
    throw std::invalid_argument("humans per scene must be 1..10, got " +
                                std::to_string(options.max_humans));
  }
}

}  // namespace

ValidationReport validate_against_ground_truth(
    const CellModel& cell, const CspaceGrid& grid, const LutSet& luts,
    const RobotSilhouettes& silhouettes, const ValidationOptions& options,
    const std::function<void(std::size_t, std::size_t)>& progress) {
  check_options(cell, options);
  SensorSettings sensor;
  sensor.seed = options.seed;
  SimulatedCell sim = simulate_cell(cell, sensor);
  const SimulatedReference reference =
      simulated_reference(sim, cell, options.reference_frames, options.seed);
  SensingPipeline pipeline(cell, grid, luts, silhouettes, reference.frames, {}, options.fusion);

  ValidationReport report;
  std::vector<double> fusion_ms;
  std::vector<double> features_ms;
  double phantom_sum = 0.0;
  double forbidden_share_sum = 0.0;
  std::mt19937_64 rng(options.seed);
  for (std::size_t s = 0; s < options.scenes; ++s) {
    const Scene scene = random_scene(cell, grid, rng, options.max_humans);
    const auto frames = sim.render(SimScene{scene.q, scene.humans}, 10 * s, 0.1 * static_cast<double>(s));
    const CellSet& forbidden = pipeline.process(frames, scene.q);
    fusion_ms.push_back(pipeline.times().fusion_ms);
    features_ms.push_back(pipeline.times().features_ms);
    forbidden_share_sum += static_cast<double>(forbidden.count()) / grid.cell_count();

    // How many cameras saw each human (after robot removal).
    std::vector<int> seen_by(scene.humans.size(), 0);
    std::vector<PlacedShape> obstacles;
    std::vector<std::string> obstacle_names;
    std::vector<int> obstacle_human;
    for (std::size_t h = 0; h < scene.humans.size(); ++h) {
      auto surfaces = sim.moving_surfaces(SimScene{scene.q, {scene.humans[h]}});
      surfaces.erase(surfaces.begin());  // the robot
      for (std::size_t c = 0; c < sim.camera_count(); ++c) {
        const FeatureMask human = feature_cells_of(sim.coverage(c, surfaces), cell.feature_grid);
        if (pipeline.observations()[c].known && human.intersects(pipeline.fusion().obstacles(c))) {
          ++seen_by[h];
        }
      }
      for (auto& part : human_shapes(scene.humans[h])) {
        obstacles.push_back(std::move(part));
        obstacle_names.push_back("human " + std::to_string(h + 1));
        obstacle_human.push_back(static_cast<int>(h));
      }
    }
    for (std::size_t b = 0; b < cell.obstacles.size(); ++b) {
      obstacles.push_back(cell.obstacles[b]);
      obstacle_names.push_back(cell.config.obstacles.at(b).name);
      obstacle_human.push_back(-1);
    }
    const GroundTruth truth(obstacles);

    for (std::size_t k = 0; k < options.configurations_per_scene; ++k) {
      std::vector<double> q = random_q(grid, rng);
      if (k % 2 == 1 && !scene.humans.empty()) {  // turned towards a human
        const auto& target = scene.humans[k / 2 % scene.humans.size()].position_m;
        q[0] = std::clamp(std::atan2(target.y(), target.x()) +
                              std::uniform_real_distribution<double>(-0.3, 0.3)(rng),
                          grid.joint(0).lo_rad, grid.joint(0).hi_rad);
      }
      JointAngles angles;
      for (std::size_t j = 0; j < q.size(); ++j) angles.rad[j] = q[j];
      const bool is_forbidden = forbidden.test(grid.cell_containing(angles).value());
      const auto hit = truth.first_colliding_obstacle(collision_shapes_at(*cell.robot, q));
      ++report.configs_checked;
      if (!hit) {
        ++report.free;
        report.false_positives += is_forbidden ? 1 : 0;
        continue;
      }
      ++report.colliding;
      const int human = obstacle_human[*hit];
      const int seeing = human < 0 ? static_cast<int>(sim.camera_count())
                                   : seen_by[static_cast<std::size_t>(human)];
      if (human >= 0 && seeing < options.fusion.camera_threshold) {
        ++report.unseen;
        continue;
      }
      if (!is_forbidden) {
        ++report.missed;
        if (report.missed_cases.size() < kMissedCasesKept) {
          report.missed_cases.push_back(MissedCollision{s, q, obstacle_names[*hit], seeing});
        }
      }
    }

    // Phantom cells: critical cells far from every human.
    const CellSet& critical = pipeline.fusion().critical();
    std::vector<CellIndex> critical_cells;
    for (CellIndex c = critical.next_set(0); c < critical.cell_count(); c = critical.next_set(c + 1)) {
      critical_cells.push_back(c);
    }
    if (!critical_cells.empty() && !scene.humans.empty()) {
      std::vector<PlacedShape> bodies;
      for (const auto& human : scene.humans) {
        for (auto& part : human_shapes(human)) bodies.push_back(std::move(part));
      }
      const GroundTruth humans(bodies);
      std::size_t phantoms = 0;
      const std::size_t samples = std::min(options.phantom_samples, critical_cells.size());
      for (std::size_t i = 0; i < samples; ++i) {
        const CellIndex pick = critical_cells[std::uniform_int_distribution<std::size_t>(
            0, critical_cells.size() - 1)(rng)];
        const JointAngles centre = grid.cell_centre(grid.coords_of(pick).value()).value();
        const std::vector<double> q(centre.rad, centre.rad + grid.joint_count());
        if (humans.min_distance_m(collision_shapes_at(*cell.robot, q)) > options.phantom_distance_m) {
          ++phantoms;
        }
      }
      phantom_sum += static_cast<double>(phantoms) / static_cast<double>(samples) *
                     static_cast<double>(critical_cells.size());
    }
    if (progress) progress(s + 1, options.scenes);
  }
  report.scenes = options.scenes;
  report.false_positive_rate =
      report.free == 0 ? 0.0 : static_cast<double>(report.false_positives) / static_cast<double>(report.free);
  report.phantom_cells = phantom_sum / static_cast<double>(options.scenes);
  report.forbidden_share = forbidden_share_sum / static_cast<double>(options.scenes);
  report.fusion_ms_p99 = percentile(fusion_ms, 0.99);
  report.features_ms_p99 = percentile(features_ms, 0.99);
  return report;
}

}  // namespace safecell
