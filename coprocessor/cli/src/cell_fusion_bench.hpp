#pragma once
// `safecell bench --cell FILE`: the sensing pipeline's fusion on another cell's grid (such as a
// 6 cm max-move, 16 million cells) against the default cell in the same run. Both run the demo's
// frames from when the person walks in (rendered before the clock starts) through the real
// pipeline, one thread, and report each frame's fusion time (robot removal, back-projection,
// the camera vote, static obstacles): median, p99 and worst, with the ratio to the default cell.
// Twice: with every frame's map fused, and as the service runs them, where a frame in which the
// protective separation stops the robot makes no map (every cell is forbidden then).
// The maps of every kMapSampleStride-th frame can be written (map_sequence_writer.hpp) for the
// controller's benchmark program, which reports what its map store needs to hold them.
// Private to the CLI.

#include <cstddef>
#include <cstdint>
#include <ostream>
#include <string>

namespace safecell {

struct CellFusionFigures {
  std::string cell;         // the cell's name
  std::uint32_t cells = 0;  // of its C-space grid
  double m_max_m = 0.0;
  double lut_bytes_per_camera = 0.0;  // LUT-2 with block levels and differences
  bool tables_built = false;          // built by this run (false: from the cache)
  double tables_build_s = 0.0;
  int frames = 0;
  double fusion_p50_ms = 0.0;
  double fusion_p99_ms = 0.0;
  double fusion_max_ms = 0.0;
  // As the service runs the frames (sensing_pipeline.hpp, skip_map_when_too_close), and how many
  // frames the separation stopped the robot in.
  double served_fusion_p50_ms = 0.0;
  double served_fusion_p99_ms = 0.0;
  double served_fusion_max_ms = 0.0;
  int frames_stopped = 0;
  double features_p50_ms = 0.0;
  double forbidden_share_mean = 0.0;  // of the maps over the frames
  double forbidden_share_max = 0.0;
  // The controller's map store (MapStoreLayout, default layout) holding the sampled maps, as
  // safecell-controller-bench reports it; map_store_maps 0: not measured.
  int map_store_maps = 0;
  double map_store_bytes = 0.0;
  double map_store_blocks = 0.0;
  double map_store_mixed_blocks_max = 0.0;
  double map_store_degraded_blocks_max = 0.0;  // held as forbidden: the pool was too small
  double map_store_inexact_maps = 0.0;         // not applied, or not held bit for bit as sent
};

// Every how many frames a fused map is written for the map store's figures (30 of 300 frames: a
// 6 cm grid's maps take 2 MB each).
inline constexpr std::size_t kMapSampleStride = 10;

// cell_path: empty for the default cell; lut_cache: empty for the default folder. Messages
// (tables built, references) go to `log`. Both passes run every frame once, taking turns going
// first a second of frames (30) at a time. maps_path: where to write the fused maps of frames
// 0, kMapSampleStride, ... (empty: none); returns with map_store_maps still 0.
CellFusionFigures measure_cell_fusion(const std::string& cell_path, const std::string& lut_cache,
                                      int frames, const std::string& maps_path, std::ostream& log);

}  // namespace safecell
