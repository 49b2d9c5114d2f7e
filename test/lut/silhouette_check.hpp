#pragma once
// The property every LUT-1 source must have: for random configurations anywhere inside random
// cells, every pixel the rendered robot covers lies in a feature cell of the cell's silhouette.

#include <gtest/gtest.h>

#include <random>

#include "model_fixture.hpp"
#include "safecell/silhouettes/robot_silhouettes.hpp"
#include "safecell/sim/cell_simulation.hpp"
#include "safecell/test/property.hpp"

namespace safecell::test {

inline void expect_silhouettes_hold_rendered_robot(const CellModel& cell, const CspaceGrid& grid,
                                                   const RobotSilhouettes& silhouettes,
                                                   int iterations) {
  SimulatedCell sim = simulate_cell(cell, SensorSettings{});
  const FeatureGrid& features = cell.feature_grid;
  PropertyRun run(iterations);
  std::uniform_int_distribution<CellIndex> any_cell(0, grid.cell_count() - 1);
  for (int i = 0; i < run.iterations(); ++i) {
    const CellIndex cell_index = any_cell(run.rng());
    const auto q = configuration_in(grid, cell_index, run.rng());
    for (std::size_t camera = 0; camera < sim.camera_count(); ++camera) {
      FeatureMask silhouette(features);
      silhouettes.add_silhouette(cell_index, camera, silhouette);
      const cv::Mat covered = sim.robot_coverage(camera, q);
      for (int y = 0; y < covered.rows; ++y) {
        for (int x = 0; x < covered.cols; ++x) {
          if (covered.at<std::uint8_t>(y, x) == 0) continue;
          ASSERT_TRUE(silhouette.test(x / features.cell_width_px(), y / features.cell_height_px()))
              << "camera " << camera << " pixel " << x << "," << y << " cell " << cell_index;
        }
      }
    }
  }
}

}  // namespace safecell::test
