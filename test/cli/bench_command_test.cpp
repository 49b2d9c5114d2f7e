#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <cmath>

#include "cli_run.hpp"
#include "coarse_cell.hpp"

namespace safecell {
namespace {

// The fusion on another cell's grid against a baseline cell, over the demo's frames: the keys and
// their sense (here the coarse cell against itself, so that its tables take a moment). 40 frames:
// the fused and the served pass each go first for one turn of 30.
TEST(BenchCommand, CellFusionComparesTwoCellsOnTheSameFrames) {
  const test::ScratchFolder scratch("safecell-bench-cell");
  const auto cell = test::write_coarse_cell(scratch.path()).string();
  const auto cache = (scratch.path() / "cache").string();
  const test::CliRun run = test::safecell_cli({"bench", "--cell", cell, "--baseline-cell", cell,
                                               "--frames", "40", "--lut-cache", cache, "--json"});
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const auto report = nlohmann::json::parse(run.out);
  for (const char* side : {"baseline", "cell"}) {
    const auto& figures = report[side];
    EXPECT_EQ(figures["frames"].get<int>(), 40) << side;
    EXPECT_GT(figures["fusion_p50_ms"].get<double>(), 0.0) << side;
    EXPECT_GE(figures["fusion_p99_ms"].get<double>(), figures["fusion_p50_ms"].get<double>());
    EXPECT_GE(figures["fusion_max_ms"].get<double>(), figures["fusion_p99_ms"].get<double>());
    EXPECT_GT(figures["lut_bytes_per_camera"].get<double>(), 0.0) << side;
    // Served: a map is made unless the separation stops the robot, so it takes time too.
    EXPECT_GE(figures["served_fusion_p99_ms"].get<double>(),
              figures["served_fusion_p50_ms"].get<double>());
    EXPECT_GE(figures["served_fusion_max_ms"].get<double>(),
              figures["served_fusion_p99_ms"].get<double>());
    EXPECT_GT(figures["served_fusion_max_ms"].get<double>(), 0.0) << side;
    EXPECT_GE(figures["frames_stopped"].get<int>(), 0) << side;
    EXPECT_LE(figures["frames_stopped"].get<int>(), 40) << side;
    // The person walks in: some of the map is forbidden, not all of it.
    EXPECT_GT(figures["forbidden_share_max"].get<double>(), 0.0) << side;
    EXPECT_LT(figures["forbidden_share_mean"].get<double>(), 1.0) << side;
  }
  EXPECT_EQ(report["baseline"]["cells"], report["cell"]["cells"]);
  EXPECT_GT(report["fusion_p99_ratio"].get<double>(), 0.0);
  // The controller's map store holding every 10th fused map: one block per 512 cells, some of
  // them mixed (the person walks in), and the default store holds each bit for bit.
  const auto& cell_figures = report["cell"];
  EXPECT_EQ(cell_figures["map_store_maps"].get<int>(), 4);
  EXPECT_EQ(cell_figures["map_store_blocks"].get<double>(),
            std::ceil(cell_figures["cells"].get<double>() / 512.0));
  EXPECT_GT(cell_figures["map_store_mixed_blocks_max"].get<double>(), 0.0);
  EXPECT_LE(cell_figures["map_store_mixed_blocks_max"].get<double>(),
            cell_figures["map_store_blocks"].get<double>());
  EXPECT_EQ(cell_figures["map_store_degraded_blocks_max"].get<double>(), 0.0);
  EXPECT_EQ(cell_figures["map_store_inexact_maps"].get<double>(), 0.0);
  // Room for the mixed blocks it held, 512 bits each.
  EXPECT_GT(cell_figures["map_store_bytes"].get<double>(),
            cell_figures["map_store_mixed_blocks_max"].get<double>() * 64.0);

  const test::CliRun absurd =
      test::safecell_cli({"bench", "--cell", cell, "--frames", "3", "--lut-cache", cache});
  EXPECT_EQ(absurd.exit_code, 2) << absurd.err;
  EXPECT_NE(absurd.err.find("--frames"), std::string::npos) << absurd.err;
}

// Runs the real benchmarks briefly: proves the keys and their sense, never the speed.
TEST(BenchCommand, JsonCarriesTheNamedFiguresOfEveryBenchmark) {
  const test::CliRun run = test::safecell_cli({"bench", "--json", "--quick"});
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const auto report = nlohmann::json::parse(run.out);
  for (const char* key :
       {"features_ms", "features_worst_ms", "health_check_ms", "sim_render_ms",
        "sim_render_worst_ms", "fusion_ms", "fusion_worst_ms", "fusion_baseline_ms",
        "fusion_speedup", "lut_bytes_per_camera", "lut_build_s", "frame_encode_us",
        "frame_check_us", "crc_mb_s", "delta_bytes_p50", "delta_bytes_p99", "keyframe_bytes",
        "delta_encode_us", "protective_separation_ms"}) {
    ASSERT_TRUE(report.contains(key)) << key;
    EXPECT_GT(report[key].get<double>(), 0.0) << key;
  }
  EXPECT_GE(report["features_worst_ms"].get<double>(), report["features_ms"].get<double>());
  const auto& masks = report["benchmarks"]["four_frames_to_blocked_masks"]["counters"];
  EXPECT_GT(masks["blocked_cells"].get<double>(), 0.0);  // the human is seen
  EXPECT_EQ(masks["blocked_cells_empty_scene"].get<double>(), 0.0);
  // The health check timed its whole path: no frame ended early as a fault.
  EXPECT_EQ(
      report["benchmarks"]["camera_health_check_one_frame"]["counters"]["faults"].get<double>(),
      0.0);
  // The fusion sees the person near the robot, and the tables stay within the 5 MB target.
  const auto& fusion = report["benchmarks"]["fusion_typical_scene"]["counters"];
  EXPECT_GT(fusion["obstacle_pixels"].get<double>(), 0.0);
  EXPECT_GT(fusion["forbidden_cells"].get<double>(), fusion["static_cells"].get<double>());
  EXPECT_LE(report["lut_bytes_per_camera"].get<double>(), 5e6);
  // Map updates: a delta is at least one frame's header and CRC; the person changes the map.
  EXPECT_GE(report["delta_bytes_p50"].get<double>(), 48.0);
  EXPECT_GE(report["delta_bytes_p99"].get<double>(), report["delta_bytes_p50"].get<double>());
  EXPECT_GE(report["keyframe_bytes"].get<double>(), 48.0);
  // End to end with safecell-controller as its own process: the maps went through the pipeline
  // (hardly any all forbidden for want of the robot's pose), and maps reached the
  // controller later than they were sent. How many the controller applied depends on speed (under
  // the sanitizers it falls behind), so that figure is reported, not asserted.
  for (const char* key :
       {"e2e_latency_p50_ms", "e2e_latency_p99_ms", "e2e_to_sent_p50_ms", "e2e_features_p50_ms",
        "e2e_fusion_p50_ms", "service_fps", "sustained_fps"}) {
    ASSERT_TRUE(report.contains(key)) << key;
    EXPECT_GT(report[key].get<double>(), 0.0) << key;
  }
  // The stages are timed inside exposure -> sent, frame by frame: what is left is never negative.
  EXPECT_GE(report["e2e_rest_p50_ms"].get<double>(), 0.0);
  // A controller stall of more than 20 ms (this VM has them) leaves the robot's pose unknown for
  // a frame, which is then rightly all forbidden; the bug this guards against made a third of them.
  const int frames = report["e2e_frames"].get<int>();
  EXPECT_LE(report["e2e_all_forbidden_frames"].get<int>() * 10, frames) << "of " << frames;
  EXPECT_TRUE(report.contains("e2e_updates_not_applied"));
  // Latency is measured on the controller's clock, "sent" on the coprocessor's; no map may be
  // applied before its sending began, within the clock offset estimate's error bound and half a
  // millisecond of rounding. Update by update: the p50s of all frames sent and of the frames
  // applied are of different sets. (Against the moment the send had returned instead, a run
  // beside another test had a map applied 5.2 ms "before": the sending thread lost the CPU.)
  EXPECT_GE(report["e2e_sent_to_applied_min_ms"].get<double>(),
            -(report["e2e_clock_uncertainty_max_ms"].get<double>() + 0.5))
      << "the clock offset's error bound: " << report["e2e_clock_uncertainty_max_ms"];
  EXPECT_GE(report["e2e_latency_p99_ms"].get<double>(), report["e2e_latency_p50_ms"].get<double>());
}

}  // namespace
}  // namespace safecell
