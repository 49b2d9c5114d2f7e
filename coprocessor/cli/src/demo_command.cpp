#include "safecell/cli/demo_command.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <nlohmann/json.hpp>
#include <random>

#include "coverage_picture.hpp"
#include "cspace_pictures.hpp"
#include "lut_loading.hpp"
#include "png_output.hpp"
#include "progress_bar.hpp"
#include "safecell/cell/cell_file.hpp"
#include "safecell/cell/cell_grid.hpp"
#include "safecell/cli/text_table.hpp"
#include "safecell/cli/validate_command.hpp"
#include "safecell/files/atomic_write.hpp"
#include "safecell/lut/model_silhouettes.hpp"
#include "safecell/pipeline/sensing_pipeline.hpp"
#include "safecell/pipeline/simulated_reference.hpp"
#include "safecell/sim/cell_simulation.hpp"
#include "safecell/sim/demo_scenario.hpp"
#include "safecell/validation/percentile.hpp"
#include "safecell/validation/scene_check.hpp"
#include "scene_options.hpp"

namespace safecell {
namespace {

namespace fs = std::filesystem;

constexpr std::size_t kReferenceFrames = 9;

std::string numbered(const char* stem, std::size_t cycle, const char* suffix) {
  char name[64];
  std::snprintf(name, sizeof name, "%s%04zu%s", stem, cycle, suffix);
  return name;
}

void write_views(const fs::path& folder, std::size_t cycle, const std::vector<cv::Mat>& frames,
                 const SensingPipeline& pipeline, const CellModel& cell) {
  std::vector<cv::Mat> tiles;
  for (std::size_t c = 0; c < frames.size(); ++c) {
    const auto& observation = pipeline.observations()[c];
    tiles.push_back(labelled(
        camera_overlay(frames[c], observation.blocked, pipeline.fusion().robot_silhouette(c),
                       pipeline.fusion().obstacles(c), cell.cameras[c].name()),
        0.5, ""));
  }
  write_png(folder / numbered("cycle_", cycle, ".png"), contact_sheet(tiles, 2));
}

void write_slices(const fs::path& folder, std::size_t cycle, const CspaceGrid& grid,
                  const SensingPipeline& pipeline, const CellSet& static_cells) {
  const CellSet& forbidden = pipeline.fusion().forbidden();
  const CellIndex at = pipeline.robot_cell();
  const std::string title = "forbidden cells, cycle " + std::to_string(cycle);
  write_png(folder / numbered("cycle_", cycle, "_joints_1_2.png"),
            forbidden_slice(grid, forbidden, static_cells, at, 0, 1, title));
  if (grid.joint_count() > 2 && grid.cells_along(2) > 1) {
    write_png(folder / numbered("cycle_", cycle, "_joints_2_3.png"),
              forbidden_slice(grid, forbidden, static_cells, at, 1, 2, title));
  }
}

}  // namespace

int run_demo(const DemoOptions& options, std::ostream& out, std::ostream& err) {
  if (!(options.seconds > 0.0 && options.seconds <= 3600.0)) {
    bad_option("--seconds", std::to_string(options.seconds), "a duration of 0..3600 s");
  }
  if (!(options.fps > 0.0 && options.fps <= 100.0)) {
    bad_option("--fps", std::to_string(options.fps), "a frame rate of 0..100 per second");
  }
  const CellModel cell = load_cell_model(load_cell_file_or_default(options.cell_path));
  const CspaceGrid grid = make_grid(cell.config);
  const fs::path out_dir(options.out_dir);
  for (const char* sub : {"views", "slices"}) fs::create_directories(out_dir / sub);

  const CachedLuts luts = cell_luts(cell, grid, ModelLutOptions{}, options.lut_cache, err);
  const ModelSilhouettes silhouettes(cell, grid, ModelLutOptions{});
  SensorSettings sensor;
  sensor.seed = options.seed;
  SimulatedCell sim = simulate_cell(cell, sensor);
  err << "reference images: median of " << kReferenceFrames << " frames of the empty cell\n";
  const SimulatedReference reference =
      simulated_reference(sim, cell, kReferenceFrames, options.seed);
  FusionSettings fusion;
  fusion.camera_threshold = cell.camera_threshold;
  SensingPipeline pipeline(cell, grid, luts.set, silhouettes, reference.frames, {}, fusion);
  const HumanWalker walker = demo_person(cell);

  const auto cycles = static_cast<std::size_t>(std::ceil(options.seconds * options.fps));
  const bool interactive = &err == &std::cerr && ProgressBar::stderr_is_terminal();
  std::mt19937_64 rng(options.seed);
  SceneCheck checks;
  std::vector<double> fusion_ms;
  std::vector<double> features_ms;
  std::size_t forbidden_max = 0;
  double forbidden_sum = 0.0;
  nlohmann::ordered_json timeline = nlohmann::ordered_json::array();
  for (std::size_t cycle = 0; cycle < cycles; ++cycle) {
    const double time_s = static_cast<double>(cycle) / options.fps;
    const SimScene scene = demo_scene(grid, walker, time_s);
    std::vector<cv::Mat> object_ids;
    const std::vector<cv::Mat> frames = sim.render(scene, cycle, time_s, &object_ids);
    const CellSet& forbidden = pipeline.process(frames, scene.q);
    const SceneUnderTest under_test{scene,  object_ids, forbidden, fusion.camera_threshold,
                                    "demo", cycle};
    const SceneCheck check =
        check_scene(cell, grid, sim, under_test, options.checks_per_cycle, rng);
    checks += check;
    fusion_ms.push_back(pipeline.times().fusion_ms);
    features_ms.push_back(pipeline.times().features_ms);
    const std::size_t forbidden_cells = forbidden.count();
    forbidden_max = std::max(forbidden_max, forbidden_cells);
    forbidden_sum += static_cast<double>(forbidden_cells);

    std::string blocked;
    std::vector<std::size_t> blocked_per_camera;
    for (const auto& observation : pipeline.observations()) {
      blocked_per_camera.push_back(observation.blocked.count());
      blocked += (blocked.empty() ? "" : "/") + std::to_string(observation.blocked.count());
    }
    timeline.push_back({{"cycle", cycle},
                        {"time_s", time_s},
                        {"humans", scene.humans.size()},
                        {"blocked_cells", blocked_per_camera},
                        {"obstacle_cells", pipeline.fusion().counts().obstacle_pixels},
                        {"forbidden_cells", forbidden_cells},
                        {"robot_cell_forbidden", forbidden.test(pipeline.robot_cell())},
                        {"features_ms", pipeline.times().features_ms},
                        {"fusion_ms", pipeline.times().fusion_ms}});
    const std::string status =
        "cycle " + std::to_string(cycle) + "  t " + fixed(time_s, 1) + " s  humans " +
        std::to_string(scene.humans.size()) + "  blocked " + blocked + "  forbidden " +
        grouped(forbidden_cells) + " (" +
        fixed(100.0 * static_cast<double>(forbidden_cells) / grid.cell_count(), 1) +
        " %)  features " + fixed(pipeline.times().features_ms, 1) + " ms  fusion " +
        fixed(pipeline.times().fusion_ms, 1) + " ms  missed " + std::to_string(checks.missed);
    if (interactive) {
      err << '\r' << status << "   " << std::flush;
    } else if (cycle % static_cast<std::size_t>(std::max(1.0, options.fps)) == 0) {
      err << status << '\n';
    }
    if (options.views_every > 0 && cycle % static_cast<std::size_t>(options.views_every) == 0) {
      write_views(out_dir / "views", cycle, frames, pipeline, cell);
      write_slices(out_dir / "slices", cycle, grid, pipeline, luts.set.static_cells);
    }
  }
  if (interactive) err << '\n';

  CoverageOptions coverage;
  coverage.step_m = kBlindSpotStep_m;
  write_png(out_dir / "floor_coverage.png", floor_plan(cell, floor_coverage(cell, grid, coverage)));

  nlohmann::ordered_json summary;
  summary["cycles"] = cycles;
  summary["seconds"] = options.seconds;
  summary["fps"] = options.fps;
  summary["cell"] = cell.config.name;
  summary["c_space_cells"] = grid.cell_count();
  summary["fusion_ms_p50"] = percentile(fusion_ms, 0.5);
  summary["fusion_ms_p99"] = percentile(fusion_ms, 0.99);
  summary["features_ms_p99"] = percentile(features_ms, 0.99);
  summary["forbidden_cells_max"] = forbidden_max;
  summary["forbidden_cells_mean"] = forbidden_sum / static_cast<double>(cycles);
  summary["configs_checked"] = checks.configs_checked;
  summary["colliding_checked"] = checks.colliding;
  summary["missed"] = checks.missed;
  summary["unseen"] = checks.unseen;
  summary["false_positive_rate"] = checks.false_positive_rate();
  summary["needless_stop_share"] = checks.needless_stop_share();
  summary["lut_file"] = luts.file.string();
  summary["lut_built_now"] = luts.built;
  summary["timeline"] = std::move(timeline);
  const std::string text = summary.dump(2) + "\n";
  write_file_atomically(out_dir / "summary.json", text);

  out << "demo: " << cycles << " cycles of " << fixed(options.seconds, 1) << " s at "
      << fixed(options.fps, 0) << " frames/s on " << cell.config.name << "\n"
      << "  fusion p50 " << fixed(percentile(fusion_ms, 0.5), 2) << " ms, p99 "
      << fixed(percentile(fusion_ms, 0.99), 2) << " ms; features p99 "
      << fixed(percentile(features_ms, 0.99), 2) << " ms\n"
      << "  forbidden cells: at most " << grouped(forbidden_max) << " of "
      << grouped(grid.cell_count()) << "\n"
      << "  ground truth: " << grouped(checks.configs_checked) << " configurations checked, "
      << checks.colliding << " colliding, missed " << checks.missed << "\n"
      << "  report: " << out_dir.string()
      << " (summary.json, views/, slices/, floor_coverage.png)\n";
  return checks.missed == 0 ? 0 : kExitValidationFailed;
}

}  // namespace safecell
