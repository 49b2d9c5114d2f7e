#include "safecell/validation/ground_truth_validation.hpp"

#include <algorithm>
#include <atomic>
#include <mutex>
#include <stdexcept>
#include <thread>

#include "safecell/pipeline/sensing_pipeline.hpp"
#include "safecell/sim/cell_simulation.hpp"
#include "safecell/sim_sources/simulated_reference.hpp"
#include "safecell/validation/percentile.hpp"
#include "safecell/validation/separation_check.hpp"

namespace safecell {
namespace {

std::uint64_t splitmix64(std::uint64_t state) {
  std::uint64_t z = state + 0x9E3779B97F4A7C15ull;
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
  return z ^ (z >> 31);
}

// Scene s's own generator: the same for the same seed and s, whoever runs it.
std::mt19937_64 scene_generator(std::uint64_t seed, std::size_t scene) {
  return std::mt19937_64(splitmix64(splitmix64(seed) ^ static_cast<std::uint64_t>(scene)));
}

void check_options(const CellModel& cell, const ValidationOptions& options) {
  if (!cell.robot) throw std::invalid_argument("validation needs a cell with a robot model");
  if (options.scenes == 0 || options.configurations_per_scene == 0) {
    throw std::invalid_argument("validation needs at least one scene and one configuration");
  }
  if (options.limits.max_humans < 1 || options.limits.max_humans > 10) {
    throw std::invalid_argument("humans per scene must be 1..10, got " +
                                std::to_string(options.limits.max_humans));
  }
  if (options.limits.max_objects < 0 || options.limits.max_objects > 10) {
    throw std::invalid_argument("objects per scene must be 0..10, got " +
                                std::to_string(options.limits.max_objects));
  }
  if (options.shard.count < 1 || options.shard.index < 1 ||
      options.shard.index > options.shard.count || options.shard.count > options.scenes) {
    throw std::invalid_argument(
        "shard " + std::to_string(options.shard.index) + "/" + std::to_string(options.shard.count) +
        ": expected K/N with 1 <= K <= N <= the scenes (" + std::to_string(options.scenes) + ")");
  }
}

// What one scene gave.
struct SceneResult {
  ValidationReport report;
  double fusion_ms = 0.0;
  double features_ms = 0.0;
};

// One thread's simulated cell and pipeline (neither is thread-safe).
class Worker {
 public:
  // cell: the model; world: the simulated cell as it really is (model_error.hpp).
  Worker(const CellModel& cell, const CellModel& world, const CspaceGrid& grid, const LutSet& luts,
         const RobotSilhouettes& silhouettes, const std::vector<cv::Mat>& reference,
         const ValidationOptions& options)
      : world_(world),
        grid_(grid),
        options_(options),
        sim_(simulate_cell(world, sensor_of(options))),
        pipeline_(cell, grid, luts, silhouettes, reference, {}, options.fusion),
        no_masks_(luts, silhouettes, options.fusion) {}

  SceneResult run(std::size_t s) {
    std::mt19937_64 rng = scene_generator(options_.seed, s);
    const SceneStratum wanted = kAllSceneStrata[s % kSceneStrata];
    const StratifiedScene placed = make_scene(wanted, world_, grid_, options_.limits, rng);
    std::vector<cv::Mat> object_ids;
    const auto frames =
        sim_.render(placed.scene, 10 * s, 0.1 * static_cast<double>(s), &object_ids);
    const CellSet* forbidden = &pipeline_.process(frames, placed.scene.q);
    const ForbiddenMapFusion* fusion = &pipeline_.fusion();
    if (options_.negative_control == NegativeControl::kEmptyMasks) {
      std::vector<CameraObservation> blind = pipeline_.observations();
      for (auto& observation : blind) observation.blocked.clear();
      forbidden = &no_masks_.fuse(blind, pipeline_.robot_cell());
      fusion = &no_masks_;
    }
    obstacles_.clear();
    for (std::size_t c = 0; c < fusion->camera_count(); ++c) {
      obstacles_.push_back(fusion->obstacles(c));
    }
    SceneResult result;
    result.fusion_ms = pipeline_.times().fusion_ms;
    result.features_ms = pipeline_.times().features_ms;
    const SceneUnderTest under_test{placed.scene,
                                    object_ids,
                                    *forbidden,
                                    options_.fusion.camera_threshold,
                                    to_string(placed.stratum),
                                    s,
                                    &obstacles_,
                                    options_.needless_stops_traced_per_scene,
                                    &fusion->parts()};
    static_cast<SceneCheck&>(result.report) =
        check_scene(world_, grid_, sim_, under_test, options_.configurations_per_scene, rng);
    if (const ProtectiveSeparation* separation = pipeline_.separation()) {
      result.report.separation =
          check_separation(world_, placed.scene, object_ids, options_.fusion.camera_threshold,
                           separation->separation_m(), pipeline_.separation_verdict().speed_limit,
                           pipeline_.separation_verdict().clear_m);
    }
    result.report.scenes = 1;
    result.report.objects = placed.scene.objects.size();
    result.report.forbidden_share_sum =
        static_cast<double>(forbidden->count()) / grid_.cell_count();
    result.report.scenes_per_stratum[to_string(placed.stratum)] = 1;
    return result;
  }

 private:
  static SensorSettings sensor_of(const ValidationOptions& options) {
    SensorSettings sensor;
    sensor.seed = options.seed;
    return sensor;
  }

  const CellModel& world_;
  const CspaceGrid& grid_;
  const ValidationOptions& options_;
  SimulatedCell sim_;
  SensingPipeline pipeline_;
  ForbiddenMapFusion no_masks_;  // the empty-masks negative control
  std::vector<FeatureMask> obstacles_;
};

}  // namespace

SceneRange scenes_of_shard(std::size_t scenes, const Shard& shard) {
  return {scenes * (shard.index - 1) / shard.count, scenes * shard.index / shard.count};
}

ValidationReport& ValidationReport::operator+=(const ValidationReport& other) {
  SceneCheck::operator+=(other);
  scenes += other.scenes;
  objects += other.objects;
  forbidden_share_sum += other.forbidden_share_sum;
  separation += other.separation;
  for (const auto& [name, count] : other.scenes_per_stratum) scenes_per_stratum[name] += count;
  fusion_ms_p99 = std::max(fusion_ms_p99, other.fusion_ms_p99);
  features_ms_p99 = std::max(features_ms_p99, other.features_ms_p99);
  return *this;
}

ValidationReport validate_against_ground_truth(
    const CellModel& cell, const CspaceGrid& grid, const LutSet& luts,
    const RobotSilhouettes& silhouettes, const ValidationOptions& options,
    const std::function<void(std::size_t, std::size_t)>& progress) {
  check_options(cell, options);
  ValidationOptions effective = options;
  if (options.negative_control == NegativeControl::kEnvelopeRemoval) {
    effective.fusion.removal = RobotRemoval::kPlain;
  }
  const LutSet damaged = options.negative_control == NegativeControl::kDroppedStrip
                             ? with_strip_dropped(luts, grid)
                             : LutSet{};
  const LutSet& tables =
      options.negative_control == NegativeControl::kDroppedStrip ? damaged : luts;

  const CellModel world = world_with_error(cell, options.model_error, options.seed);
  std::vector<cv::Mat> reference;
  {
    SimulatedCell sim = simulate_cell(world, SensorSettings{.seed = options.seed});
    reference = simulated_reference(sim, world, options.reference_frames, options.seed).frames;
  }
  const SceneRange range = scenes_of_shard(options.scenes, options.shard);
  const std::size_t count = range.end - range.first;
  const unsigned hardware = std::max(1u, std::thread::hardware_concurrency());
  const auto threads = static_cast<unsigned>(
      std::min<std::size_t>(options.threads == 0 ? hardware : options.threads, count));

  std::vector<SceneResult> results(count);
  std::atomic<std::size_t> next{0};
  std::size_t done = 0;
  std::mutex progress_mutex;
  std::exception_ptr failure;
  const auto work = [&] {
    try {
      Worker worker(cell, world, grid, tables, silhouettes, reference, effective);
      for (std::size_t k = next++; k < count; k = next++) {
        results[k] = worker.run(range.first + k);
        const std::lock_guard lock(progress_mutex);
        ++done;
        if (progress) progress(done, count);
      }
    } catch (...) {
      const std::lock_guard lock(progress_mutex);
      if (!failure) failure = std::current_exception();
      next = count;  // the others stop after their scene
    }
  };
  std::vector<std::thread> pool;
  for (unsigned t = 1; t < threads; ++t) pool.emplace_back(work);
  work();
  for (auto& thread : pool) thread.join();
  if (failure) std::rethrow_exception(failure);

  ValidationReport report;
  std::vector<double> fusion_ms, features_ms;
  for (const SceneResult& result : results) {  // in scene order: the same report every time
    report += result.report;
    fusion_ms.push_back(result.fusion_ms);
    features_ms.push_back(result.features_ms);
  }
  report.fusion_ms_p99 = percentile(fusion_ms, 0.99);
  report.features_ms_p99 = percentile(features_ms, 0.99);
  return report;
}

}  // namespace safecell
