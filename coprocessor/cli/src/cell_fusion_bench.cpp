#include "cell_fusion_bench.hpp"

#include <algorithm>
#include <vector>

#include "safecell/bench/map_sequence_writer.hpp"
#include "safecell/sim/demo_scenario.hpp"
#include "safecell/validation/percentile.hpp"
#include "simulated_sensing.hpp"

namespace safecell {

CellFusionFigures measure_cell_fusion(const std::string& cell_path, const std::string& lut_cache,
                                      int frames, const std::string& maps_path, std::ostream& log) {
  SimulatedSensing sensing(cell_path, lut_cache, 1, log);
  CellFusionFigures figures;
  figures.cell = sensing.cell.config.name;
  figures.cells = sensing.grid.cell_count();
  figures.m_max_m = sensing.cell.config.m_max_m;
  double bytes = 0.0;
  for (const auto& camera : sensing.luts.set.cameras) {
    bytes += static_cast<double>(camera.pixel_table_bytes());
  }
  figures.lut_bytes_per_camera =
      bytes / static_cast<double>(std::max<std::size_t>(1, sensing.luts.set.cameras.size()));
  figures.tables_built = sensing.luts.built;
  figures.tables_build_s = sensing.luts.build_s;
  figures.frames = frames;

  // The frames first, so that the rendering is outside what is timed.
  const HumanWalker person = demo_person(sensing.cell);
  std::vector<SimScene> scenes;
  std::vector<std::vector<cv::Mat>> frame_sets;
  for (int frame = 0; frame < frames; ++frame) {
    const double time_s = kDemoHumanEnters_s + frame / 30.0;
    scenes.push_back(demo_scene(sensing.grid, person, time_s));
    frame_sets.push_back(
        sensing.sim.render(scenes.back(), static_cast<std::size_t>(frame), time_s));
  }
  // Two passes over the frames: every map fused, as validation and the demo's pictures run the
  // pipeline; and as the service runs it, no map made when the separation stops the robot. They
  // take turns going first, a second of frames at a time, so that neither pass is always the one
  // that finds the machine warm (or busy).
  std::vector<double> fusion_ms;
  std::vector<double> features_ms;
  std::vector<double> served_ms;
  double share_sum = 0.0;
  std::vector<CellSet> sampled_maps;
  const auto fuse_every_map = [&](std::size_t frame) {
    sensing.pipeline.skip_map_when_too_close(false);
    const CellSet& map = sensing.pipeline.process(frame_sets[frame], scenes[frame].q);
    fusion_ms.push_back(sensing.pipeline.times().fusion_ms);
    features_ms.push_back(sensing.pipeline.times().features_ms);
    const double share = static_cast<double>(map.count()) / static_cast<double>(figures.cells);
    share_sum += share;
    figures.forbidden_share_max = std::max(figures.forbidden_share_max, share);
    if (!maps_path.empty() && frame % kMapSampleStride == 0) sampled_maps.push_back(map);
  };
  const auto serve = [&](std::size_t frame) {
    sensing.pipeline.skip_map_when_too_close(true);
    (void)sensing.pipeline.process(frame_sets[frame], scenes[frame].q);
    served_ms.push_back(sensing.pipeline.times().fusion_ms);
    if (sensing.pipeline.separation_verdict().too_close) ++figures.frames_stopped;
  };
  constexpr std::size_t kTurn = 30;  // frames per turn: a second at 30 frames/s
  const auto count = static_cast<std::size_t>(std::max(frames, 0));
  for (std::size_t first = 0; first < count; first += kTurn) {
    const std::size_t end = std::min(count, first + kTurn);
    const bool served_first = (first / kTurn) % 2 == 1;
    for (int pass = 0; pass < 2; ++pass) {
      const bool serving = (pass == 0) == served_first;
      for (std::size_t frame = first; frame < end; ++frame) {
        if (serving) {
          serve(frame);
        } else {
          fuse_every_map(frame);
        }
      }
    }
  }
  sensing.pipeline.skip_map_when_too_close(false);
  figures.served_fusion_p50_ms = percentile(served_ms, 0.5);
  figures.served_fusion_p99_ms = percentile(served_ms, 0.99);
  figures.served_fusion_max_ms = percentile(served_ms, 1.0);
  figures.fusion_p50_ms = percentile(fusion_ms, 0.5);
  figures.fusion_p99_ms = percentile(fusion_ms, 0.99);
  figures.fusion_max_ms = percentile(fusion_ms, 1.0);
  figures.features_p50_ms = percentile(features_ms, 0.5);
  figures.forbidden_share_mean = frames > 0 ? share_sum / frames : 0.0;
  if (!maps_path.empty()) write_map_sequence_file(maps_path, sensing.grid, sampled_maps);
  return figures;
}

}  // namespace safecell
