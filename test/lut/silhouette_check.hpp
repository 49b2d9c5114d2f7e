#pragma once
// The property every LUT-1 source must have: for random configurations anywhere inside random
// cells, every pixel the rendered robot covers lies in a feature cell of the cell's silhouette.

#include <gtest/gtest.h>

#include <random>
#include <sstream>
#include <string>

#include "model_fixture.hpp"
#include "safecell/silhouettes/robot_silhouettes.hpp"
#include "safecell/sim/cell_simulation.hpp"
#include "safecell/test/property.hpp"

namespace safecell::test {

// Rendered robot pixels outside the silhouette of their cell, over `iterations` random
// configurations, and the first of them in words (empty when there is none).
struct UncoveredPixels {
  std::size_t count = 0;
  std::string first;
};

inline UncoveredPixels uncovered_robot_pixels(const CellModel& cell, const CspaceGrid& grid,
                                              const RobotSilhouettes& silhouettes, int iterations) {
  SimulatedCell sim = simulate_cell(cell, SensorSettings{});
  const FeatureGrid& features = cell.feature_grid;
  PropertyRun run(iterations);
  std::uniform_int_distribution<CellIndex> any_cell(0, grid.cell_count() - 1);
  UncoveredPixels uncovered;
  for (int i = 0; i < run.iterations(); ++i) {
    const CellIndex cell_index = any_cell(run.rng());
    const auto q = configuration_in(grid, cell_index, run.rng());
    for (std::size_t camera = 0; camera < sim.camera_count(); ++camera) {
      FeatureMask silhouette(features);
      silhouettes.add_silhouette(cell_index, camera, silhouette);
      const cv::Mat covered = sim.robot_coverage(camera, q);
      for (int y = 0; y < covered.rows; ++y) {
        for (int x = 0; x < covered.cols; ++x) {
          if (covered.at<std::uint8_t>(y, x) == 0 ||
              silhouette.test(x / features.cell_width_px(), y / features.cell_height_px())) {
            continue;
          }
          if (uncovered.count++ == 0) {
            std::ostringstream where;
            where << "camera " << camera << " pixel " << x << "," << y << " cell " << cell_index
                  << " q";
            for (const double angle : q) where << " " << angle;
            uncovered.first = where.str();
          }
        }
      }
    }
  }
  return uncovered;
}

inline void expect_silhouettes_hold_rendered_robot(const CellModel& cell, const CspaceGrid& grid,
                                                   const RobotSilhouettes& silhouettes,
                                                   int iterations) {
  const UncoveredPixels uncovered = uncovered_robot_pixels(cell, grid, silhouettes, iterations);
  EXPECT_EQ(uncovered.count, 0u) << "first: " << uncovered.first;
}

}  // namespace safecell::test
