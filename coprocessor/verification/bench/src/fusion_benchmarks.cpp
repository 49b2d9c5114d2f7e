// The fusion of paper §4.3-4.4 on the default cell: 4 blocked masks (robot and a person about
// 1.3 m from its base, against the median reference)
// -> robot removal with the model's LUT-1 -> LUT-2 back-projection -> camera threshold -> static
// obstacles -> the forbidden map. Targets (DESIGN.md §5): typical scene <= 0.1 ms, 30 % of the
// pixels blocked <= 1 ms, >= 10x faster than the paper's per-cell counting in the same run.
// The tables are built once per process before timing; the build time and the table size are
// reported as counters (lut_build_s, lut_bytes_per_camera).
#include <benchmark/benchmark.h>

#include <random>

#include "default_cell_tables.hpp"
#include "safecell/bench/project_benchmarks.hpp"
#include "safecell/cell/entry_zones.hpp"
#include "safecell/explain/cell_explanation.hpp"
#include "safecell/features/blocked_mask.hpp"
#include "safecell/features/feature_extractor.hpp"
#include "safecell/fusion/baseline_fusion.hpp"
#include "safecell/fusion/forbidden_map_fusion.hpp"
#include "safecell/pipeline/cell_fusion_settings.hpp"
#include "safecell/separation/protective_separation.hpp"
#include "safecell/sim/cell_simulation.hpp"
#include "safecell/sim_sources/simulated_reference.hpp"

namespace safecell {
namespace {

struct FusionSetUp {
  const DefaultCellTables& tables = default_cell_tables();
  const CellModel& cell = tables.cell;
  const CspaceGrid& grid = tables.grid;
  const double build_s = tables.build_s;
  const LutSet& luts = tables.luts;
  const ModelSilhouettes& silhouettes = tables.silhouettes;
  CellIndex robot_cell = 0;
  std::vector<CameraObservation> typical;         // the robot and a human near it
  std::vector<CameraObservation> thirty_percent;  // 30 % of every mask blocked

  std::vector<double> q{0.6, 0.3, 0.8, 0.0, 0.5, 0.0};  // the robot's configuration

  FusionSetUp() {
    JointAngles angles;
    for (std::size_t j = 0; j < q.size(); ++j) angles.rad[j] = q[j];
    robot_cell = grid.cell_containing(angles).value();
    SimulatedCell sim = simulate_cell(cell, SensorSettings{});
    HumanPose human;
    human.position_m = Eigen::Vector2d(1.0, -0.8);
    human.heading_rad = 2.5;
    // The reference as the pipeline makes it: the median of nine frames of the empty cell.
    const std::vector<cv::Mat> reference = simulated_reference(sim, cell, 9, 1).frames;
    const std::vector<cv::Mat> frames = sim.render(SimScene{q, {human}}, 1, 0.0);
    FeatureExtractor extractor(cell.feature_grid);
    std::mt19937_64 rng(7);
    for (std::size_t c = 0; c < frames.size(); ++c) {
      const cv::Mat mask =
          blocked_mask(extractor.extract(frames[c]), extractor.extract(reference[c]),
                       cell.feature_weights, cell.blocked_threshold);
      typical.push_back(CameraObservation{true, FeatureMask::from_image(mask)});
      thirty_percent.push_back(CameraObservation{true, blobs_covering(0.3, rng)});
    }
  }

  // Random rectangles until `share` of the feature cells are blocked.
  FeatureMask blobs_covering(double share, std::mt19937_64& rng) const {
    FeatureMask mask(cell.feature_grid);
    const auto target =
        static_cast<std::size_t>(share * static_cast<double>(cell.feature_grid.cell_count()));
    std::uniform_int_distribution<int> column(0, mask.columns() - 1);
    std::uniform_int_distribution<int> row(0, mask.rows() - 1);
    std::uniform_int_distribution<int> size(1, 8);
    while (mask.count() < target) {
      const int c0 = column(rng);
      const int r0 = row(rng);
      mask.set_rect(
          FeatureRect{static_cast<std::uint16_t>(c0), static_cast<std::uint16_t>(r0),
                      static_cast<std::uint16_t>(std::min(mask.columns() - 1, c0 + size(rng))),
                      static_cast<std::uint16_t>(std::min(mask.rows() - 1, r0 + size(rng)))});
    }
    return mask;
  }
};

const FusionSetUp& set_up() {
  static const FusionSetUp fusion;
  return fusion;
}

void report(benchmark::State& state, const FusionSetUp& fusion, const ForbiddenMapFusion& engine) {
  double pixels = 0.0;
  for (const std::size_t count : engine.counts().obstacle_pixels)
    pixels += static_cast<double>(count);
  state.counters["obstacle_pixels"] = pixels;
  state.counters["forbidden_cells"] = static_cast<double>(engine.counts().forbidden_cells);
  state.counters["static_cells"] = static_cast<double>(fusion.luts.static_cells.count());
  state.counters["lut_build_s"] = fusion.build_s;
  double bytes = 0.0;
  for (const auto& camera : fusion.luts.cameras) {
    bytes += static_cast<double>(camera.pixel_table_bytes() + camera.cell_to_pixels.bytes());
  }
  state.counters["lut_bytes_per_camera"] = bytes / static_cast<double>(fusion.luts.cameras.size());
}

void fuse(benchmark::State& state, const std::vector<CameraObservation>& observations,
          bool hidden_votes = false) {
  const FusionSetUp& fusion = set_up();
  FusionSettings settings = cell_fusion_settings(fusion.cell);
  settings.hidden_votes = hidden_votes;
  ForbiddenMapFusion engine(fusion.luts, fusion.silhouettes, settings);
  while (state.KeepRunning()) {
    benchmark::DoNotOptimize(&engine.fuse(observations, fusion.robot_cell));
    benchmark::ClobberMemory();
  }
  report(state, fusion, engine);
}

void fusion_typical_scene(benchmark::State& state) { fuse(state, set_up().typical); }

void fusion_thirty_percent_blocked(benchmark::State& state) {
  fuse(state, set_up().thirty_percent);
}

void fusion_typical_scene_hidden_votes(benchmark::State& state) {
  fuse(state, set_up().typical, true);
}

// Why a critical cell of the typical scene is critical (what the service does when the controller
// reports a slow-down or stop for it): every obstacle pixel's LUT-2 entry of every part, read.
void stop_explanation_typical_scene(benchmark::State& state) {
  const FusionSetUp& fusion = set_up();
  ForbiddenMapFusion engine(fusion.luts, fusion.silhouettes, cell_fusion_settings(fusion.cell));
  engine.fuse(fusion.typical, fusion.robot_cell);
  FusedViewsHistory history(1);
  history.record(1, engine, fusion.typical);
  const CellIndex cell = engine.critical().next_set(0);
  if (cell >= engine.critical().cell_count()) {
    state.SkipWithError("the typical scene has no critical cell");
    return;
  }
  std::size_t voting_cameras = 0;
  while (state.KeepRunning()) {
    const CellExplanation explanation = explain_cell(engine, history.find(1), cell);
    voting_cameras = 0;
    for (const PartVote& vote : explanation.parts) voting_cameras += vote.cameras.size();
    benchmark::DoNotOptimize(voting_cameras);
  }
  state.counters["voting_cameras"] = static_cast<double>(voting_cameras);
}

// The protective separation check of the typical scene (the person about 1.3 m from the base):
// each robot part grown by the default cell's S (and by each reduced speed's, down to the first
// clear level), projected into every camera, against the obstacles after robot removal. Part of
// every cycle's fusion_ms in the pipeline.
void protective_separation_typical_scene(benchmark::State& state) {
  const FusionSetUp& fusion = set_up();
  ForbiddenMapFusion engine(fusion.luts, fusion.silhouettes, cell_fusion_settings(fusion.cell));
  const std::vector<double> q = fusion.q;
  engine.fuse(fusion.typical, fusion.robot_cell, q);
  const ProtectiveSeparation check(
      fusion.cell, fusion.luts.parts, fusion.cell.ball_radius_m, FusionSettings{}.padding_m,
      separation_levels(default_protective_separation(), default_reduced_speeds()),
      fusion.cell.camera_threshold);
  std::vector<bool> known(fusion.typical.size(), true);
  std::vector<const FeatureMask*> obstacles;
  for (std::size_t c = 0; c < fusion.typical.size(); ++c) obstacles.push_back(&engine.obstacles(c));
  double speed_limit = 1.0;
  while (state.KeepRunning()) {
    speed_limit = check.check(q, known, obstacles).speed_limit;
    benchmark::DoNotOptimize(speed_limit);
  }
  // The levels checked grow as someone comes nearer: the figure is for this scene's verdict.
  state.counters["speed_limit"] = speed_limit;
}

void fusion_baseline_typical_scene(benchmark::State& state) {
  const FusionSetUp& fusion = set_up();
  BaselineFusion engine(fusion.luts, fusion.silhouettes, cell_fusion_settings(fusion.cell));
  while (state.KeepRunning()) {
    benchmark::DoNotOptimize(&engine.fuse(fusion.typical, fusion.robot_cell));
    benchmark::ClobberMemory();
  }
  state.counters["forbidden_cells"] = static_cast<double>(engine.forbidden().count());
}

// LUT-1 of model mode for one cell and all cameras: what robot removal computes each cycle.
void robot_silhouettes_of_one_cell(benchmark::State& state) {
  const FusionSetUp& fusion = set_up();
  std::vector<FeatureMask> masks(fusion.luts.cameras.size(), FeatureMask(fusion.cell.feature_grid));
  while (state.KeepRunning()) {
    for (auto& mask : masks) mask.clear();
    fusion.silhouettes.add_silhouettes(fusion.robot_cell, masks);
    benchmark::ClobberMemory();
  }
  double pixels = 0.0;
  for (const auto& mask : masks) pixels += static_cast<double>(mask.count());
  state.counters["silhouette_pixels"] = pixels;
}

// The camera vote of one robot part on the 6 cm grid's line layout (142 x 110 x 62 x 17 cells:
// 115,940 lines of joint 0's 142 cells, three words each, 2.8 MB per set): four cameras' sets of
// random cells, at least two of them, ORed into the critical lines. Counted a block at a time (what
// fusion does) and, as the baseline in the same run, level by level over the whole arrays.
constexpr std::size_t kFineGridLineWords = std::size_t{110} * 62 * 17 * 3;

void camera_votes_fine_grid(benchmark::State& state, std::size_t block_words) {
  std::mt19937_64 rng(15);
  std::vector<std::vector<std::uint64_t>> sets(4, std::vector<std::uint64_t>(kFineGridLineWords));
  for (auto& set : sets) {
    for (auto& word : set) {
      const std::uint64_t half = rng();
      word = half & rng();  // a quarter of the cells
    }
  }
  const std::vector<std::span<const std::uint64_t>> views(sets.begin(), sets.end());
  std::vector<std::vector<std::uint64_t>> scratch(2);
  std::vector<std::uint64_t> critical(kFineGridLineWords, 0);
  while (state.KeepRunning()) {
    benchmark::DoNotOptimize(or_at_least(views, 2, {}, scratch, critical, block_words));
    benchmark::ClobberMemory();
  }
  state.counters["set_bytes"] = static_cast<double>(kFineGridLineWords * sizeof(std::uint64_t));
}

void camera_votes_fine_grid_blocked(benchmark::State& state) {
  camera_votes_fine_grid(state, kAtLeastBlockWords);
}

void camera_votes_fine_grid_whole_arrays(benchmark::State& state) {
  camera_votes_fine_grid(state, kFineGridLineWords);
}

}  // namespace

void register_fusion_benchmarks() {
  register_benchmark("fusion_typical_scene", fusion_typical_scene, benchmark::kMicrosecond);
  register_benchmark("fusion_thirty_percent_blocked", fusion_thirty_percent_blocked,
                     benchmark::kMicrosecond);
  register_benchmark("fusion_baseline_typical_scene", fusion_baseline_typical_scene,
                     benchmark::kMicrosecond);
  register_benchmark("fusion_typical_scene_hidden_votes", fusion_typical_scene_hidden_votes,
                     benchmark::kMicrosecond);
  register_benchmark("stop_explanation_typical_scene", stop_explanation_typical_scene,
                     benchmark::kMicrosecond);
  register_benchmark("protective_separation_typical_scene", protective_separation_typical_scene,
                     benchmark::kMicrosecond);
  register_benchmark("robot_silhouettes_of_one_cell", robot_silhouettes_of_one_cell,
                     benchmark::kMicrosecond);
  register_benchmark("camera_votes_fine_grid_blocked", camera_votes_fine_grid_blocked,
                     benchmark::kMicrosecond);
  register_benchmark("camera_votes_fine_grid_whole_arrays", camera_votes_fine_grid_whole_arrays,
                     benchmark::kMicrosecond);
}

}  // namespace safecell
