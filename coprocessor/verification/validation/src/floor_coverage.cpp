#include "safecell/validation/floor_coverage.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "safecell/sim/cell_simulation.hpp"
#include "safecell/sim/ground_truth.hpp"
#include "safecell/validation/body_visibility.hpp"

namespace safecell {
namespace {

constexpr double kBlindSpotHeight_m = 2.0;

void check(const CellModel& cell, const CoverageOptions& options) {
  if (cell.cameras.empty()) throw std::invalid_argument("the cell has no camera to see with");
  if (!(options.step_m >= 0.02 && options.step_m <= 1.0)) {
    throw std::invalid_argument("coverage step must be 0.02..1 m, got " +
                                std::to_string(options.step_m));
  }
  if (!(options.body_radius_m >= 0.05 && options.body_radius_m <= 1.0)) {
    throw std::invalid_argument("coverage body radius must be 0.05..1 m, got " +
                                std::to_string(options.body_radius_m));
  }
  if (options.body_heights_m.empty()) throw std::invalid_argument("coverage needs a body height");
  for (const double height : options.body_heights_m) {
    if (!(height >= 0.1 && height <= 3.0)) {
      throw std::invalid_argument("coverage body height must be 0.1..3 m, got " +
                                  std::to_string(height));
    }
  }
}

PlacedShape standing_cylinder(const Eigen::Vector2d& at, double radius_m, double height_m) {
  PlacedShape body{Cylinder{radius_m, height_m}, Eigen::Isometry3d::Identity()};
  body.pose.translation() = Eigen::Vector3d(at.x(), at.y(), height_m / 2.0);
  return body;
}

}  // namespace

std::size_t FloorCoverage::reach_positions() const {
  std::size_t count = 0;
  for (int row = 0; row < rows; ++row) {
    for (int column = 0; column < columns; ++column) {
      count += at(column, row) >= 0 && position_m(column, row).norm() <= reach_m + body_radius_m;
    }
  }
  return count;
}

std::size_t FloorCoverage::reach_blind_positions() const {
  std::size_t count = 0;
  for (int row = 0; row < rows; ++row) {
    for (int column = 0; column < columns; ++column) {
      count += blind(column, row) && position_m(column, row).norm() <= reach_m + body_radius_m;
    }
  }
  return count;
}

double FloorCoverage::reach_blind_share() const {
  const std::size_t all = reach_positions();
  return all == 0 ? 0.0 : static_cast<double>(reach_blind_positions()) / static_cast<double>(all);
}

FloorCoverage floor_coverage(const CellModel& cell, const CspaceGrid& grid,
                             const CoverageOptions& options,
                             const std::function<void(std::size_t, std::size_t)>& progress) {
  check(cell, options);
  FloorCoverage coverage;
  coverage.step_m = options.step_m;
  coverage.body_radius_m = options.body_radius_m;
  coverage.camera_count = static_cast<int>(cell.cameras.size());
  coverage.camera_threshold = cell.camera_threshold;
  coverage.reach_m = grid.joint(0).l_m;
  const double half_x = cell.config.size_m[0] / 2.0 - options.wall_clearance_m;
  const double half_y = cell.config.size_m[1] / 2.0 - options.wall_clearance_m;
  coverage.columns = static_cast<int>(std::floor(2.0 * half_x / options.step_m)) + 1;
  coverage.rows = static_cast<int>(std::floor(2.0 * half_y / options.step_m)) + 1;
  coverage.first_m = Eigen::Vector2d(-half_x, -half_y);
  const std::size_t positions = coverage.index(0, coverage.rows);
  coverage.cameras_seeing.assign(positions, 0);

  // The still cell as the cameras see it; no robot, no noise needed for object ids.
  SimulatedCell sim = simulate_cell(cell, SensorSettings{});
  const std::optional<GroundTruth> statics =
      cell.obstacles.empty() ? std::nullopt : std::optional<GroundTruth>(cell.obstacles);
  const BodyCode body = body_code(BodyKind::kHuman, 0);
  const double tallest =
      *std::max_element(options.body_heights_m.begin(), options.body_heights_m.end());
  for (int row = 0; row < coverage.rows; ++row) {
    for (int column = 0; column < coverage.columns; ++column) {
      const Eigen::Vector2d at = coverage.position_m(column, row);
      int& seeing = coverage.cameras_seeing[coverage.index(column, row)];
      if (statics && statics->collides({standing_cylinder(at, options.body_radius_m, tallest)})) {
        seeing = -1;
      } else {
        for (std::size_t c = 0; c < sim.camera_count(); ++c) {
          bool every_height = true;
          for (const double height : options.body_heights_m) {
            SurfaceMesh surface =
                surface_of({standing_cylinder(at, options.body_radius_m, height)}, 0, body);
            if (!front_most_cells(sim.object_ids(c, {surface}), body, cell.feature_grid).any()) {
              every_height = false;
              break;
            }
          }
          seeing += every_height ? 1 : 0;
        }
      }
      if (progress) progress(coverage.index(column, row) + 1, positions);
    }
  }
  return coverage;
}

std::vector<PlacedShape> blind_spot_volumes(const FloorCoverage& coverage) {
  std::vector<PlacedShape> volumes;
  const double grow = coverage.body_radius_m + coverage.step_m / 2.0;
  for (int row = 0; row < coverage.rows; ++row) {
    for (int column = 0; column < coverage.columns;) {
      if (!coverage.blind(column, row)) {
        ++column;
        continue;
      }
      const int first = column;
      while (column < coverage.columns && coverage.blind(column, row)) ++column;
      const Eigen::Vector2d from = coverage.position_m(first, row);
      const Eigen::Vector2d to = coverage.position_m(column - 1, row);
      PlacedShape box{
          Box{Eigen::Vector3d(to.x() - from.x() + 2.0 * grow, 2.0 * grow, kBlindSpotHeight_m)},
          Eigen::Isometry3d::Identity()};
      box.pose.translation() =
          Eigen::Vector3d((from.x() + to.x()) / 2.0, from.y(), kBlindSpotHeight_m / 2.0);
      volumes.push_back(box);
    }
  }
  return volumes;
}

CellModel with_blind_spots_forbidden(const CellModel& cell, const FloorCoverage& coverage) {
  CellModel tables = cell;
  for (auto& volume : blind_spot_volumes(coverage)) tables.obstacles.push_back(std::move(volume));
  return tables;
}

}  // namespace safecell
