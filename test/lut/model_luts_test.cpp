#include "safecell/lut/model_luts.hpp"

#include <gtest/gtest.h>

#include <chrono>
#include <cstdlib>
#include <iostream>

#include "safecell/cell/cell_grid.hpp"
#include "safecell/cell/default_cell.hpp"
#include "safecell/lut/robot_balls.hpp"

namespace safecell {
namespace {

TEST(ModelLuts, BallCounts) {
  const CellModel cell = load_cell_model(default_cell());
  for (double r : {0.06, 0.1, 0.15}) {
    const auto b = cover_with_balls(*cell.robot, r);
    std::cerr << "r " << r << " base " << b.base.size();
    for (const auto& l : b.links) std::cerr << " " << l.size();
    std::cerr << "\n";
  }
}

TEST(ModelLuts, DefaultCellStatistics) {
  const CellModel cell = load_cell_model(default_cell());
  const CspaceGrid grid = make_grid(cell.config);
  const auto start = std::chrono::steady_clock::now();
  int last_stage = -1;
  ModelLutOptions options;
  if (const char* r = std::getenv("BALL_R")) options.ball_radius_m = std::atof(r);
  const LutSet set = build_model_luts(cell, grid, options, [&](int stage, double) {
    if (stage != last_stage) {
      std::cerr << "stage " << stage << " at " << std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() << "\n";
      last_stage = stage;
    }
  });
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::cerr << "\nbuild " << seconds << " s\n";
  for (const auto& camera : set.cameras) {
    std::size_t covered = 0;
    for (CellIndex c = 0; c < grid.cell_count(); ++c) covered += camera.cell_to_pixels.mask_of(c).count();
    std::cerr << camera.camera << " lut1 rects " << camera.cell_to_pixels.rects().size() << " bytes "
              << camera.cell_to_pixels.bytes() << " avg px " << double(covered) / grid.cell_count()
              << " | lut2 boxes " << camera.pixel_to_cells.total_boxes() << " bytes "
              << camera.pixel_to_cells.bytes() << "\n";
  }
  std::cerr << "static " << set.static_cells.count() << "\n";
}

}  // namespace
}  // namespace safecell
