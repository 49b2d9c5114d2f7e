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
#include "safecell/validation/percentile.hpp"
#include "safecell/validation/scene_check.hpp"

namespace safecell {
namespace {

constexpr double kWallClearance_m = 0.3;

// A box standing on the floor somewhere in the cell: 0.2-0.8 m a side, 0.2-1.2 m high, turned.
PlacedShape random_object(double half_x, double half_y, std::mt19937_64& rng) {
  std::uniform_real_distribution<double> side(0.2, 0.8);
  const Eigen::Vector3d size(side(rng), side(rng),
                             std::uniform_real_distribution<double>(0.2, 1.2)(rng));
  PlacedShape object{Box{size}, Eigen::Isometry3d::Identity()};
  object.pose.translate(Eigen::Vector3d(
      std::uniform_real_distribution<double>(-half_x, half_x)(rng),
      std::uniform_real_distribution<double>(-half_y, half_y)(rng), size.z() / 2.0));
  object.pose.rotate(Eigen::AngleAxisd(
      std::uniform_real_distribution<double>(-std::numbers::pi, std::numbers::pi)(rng),
      Eigen::Vector3d::UnitZ()));
  return object;
}

SimScene random_scene(const CellModel& cell, const CspaceGrid& grid, std::mt19937_64& rng,
                      int max_humans, int max_objects) {
  SimScene scene;
  scene.q = random_configuration(grid, rng);
  const auto robot = collision_shapes_at(*cell.robot, scene.q);
  const double half_x = cell.config.size_m[0] / 2.0 - kWallClearance_m;
  const double half_y = cell.config.size_m[1] / 2.0 - kWallClearance_m;
  const int humans = std::uniform_int_distribution<int>(1, max_humans)(rng);
  for (int attempt = 0; attempt < 200 && static_cast<int>(scene.humans.size()) < humans;
       ++attempt) {
    HumanPose pose;
    pose.position_m = {std::uniform_real_distribution<double>(-half_x, half_x)(rng),
                       std::uniform_real_distribution<double>(-half_y, half_y)(rng)};
    pose.heading_rad =
        std::uniform_real_distribution<double>(-std::numbers::pi, std::numbers::pi)(rng);
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
  // Objects where there is room as well, after the humans.
  const int objects = std::uniform_int_distribution<int>(0, max_objects)(rng);
  for (int attempt = 0; attempt < 200 && static_cast<int>(scene.objects.size()) < objects;
       ++attempt) {
    const PlacedShape object = random_object(half_x, half_y, rng);
    std::vector<PlacedShape> occupied = cell.obstacles;
    for (auto& body : moving_bodies(scene)) occupied.push_back(std::move(body));
    if (GroundTruth({object}).collides(robot)) continue;
    if (!occupied.empty() && GroundTruth(occupied).collides({object})) continue;
    scene.objects.push_back(object);
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
  if (options.max_objects < 0 || options.max_objects > 10) {
    throw std::invalid_argument("objects per scene must be 0..10, got " +
                                std::to_string(options.max_objects));
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
    const SimScene scene = random_scene(cell, grid, rng, options.max_humans, options.max_objects);
    report.objects += scene.objects.size();
    const auto frames = sim.render(scene, 10 * s, 0.1 * static_cast<double>(s));
    const CellSet& forbidden = pipeline.process(frames, scene.q);
    fusion_ms.push_back(pipeline.times().fusion_ms);
    features_ms.push_back(pipeline.times().features_ms);
    forbidden_share_sum += static_cast<double>(forbidden.count()) / grid.cell_count();

    const SceneCheck check =
        check_scene(cell, grid, sim, pipeline, scene, options.configurations_per_scene, rng, s);
    report += check;
    phantom_sum += estimate_phantom_cells(cell, grid, pipeline, moving_bodies(scene),
                                          options.phantom_samples, options.phantom_distance_m, rng);
    if (progress) progress(s + 1, options.scenes);
  }
  report.scenes = options.scenes;
  report.false_positive_rate = report.SceneCheck::false_positive_rate();
  report.phantom_cells = phantom_sum / static_cast<double>(options.scenes);
  report.forbidden_share = forbidden_share_sum / static_cast<double>(options.scenes);
  report.fusion_ms_p99 = percentile(fusion_ms, 0.99);
  report.features_ms_p99 = percentile(features_ms, 0.99);
  return report;
}

}  // namespace safecell
