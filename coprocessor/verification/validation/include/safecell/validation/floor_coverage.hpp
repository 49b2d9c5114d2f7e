#pragma once
// Blind spots: where on the floor a person can stand that too few cameras see. A person the
// cameras cannot see cannot be avoided, so the cell must say where that can happen (and may
// forbid the robot to reach there, blind_spot_volumes()).
//
// At every position of a floor grid (inside the walls, not inside a static obstacle) stands a
// person-sized body: an upright cylinder, 0.3 m in radius, once 0.4 m and once 2.0 m tall (a
// crouching child to a tall adult). A camera sees it when it is *visible* there
// (body_visibility.hpp: half a feature cell front-most), rendered among the static obstacles and
// without the robot; the position counts the cameras that see both heights.

#include <Eigen/Core>
#include <cstddef>
#include <functional>
#include <vector>

#include "safecell/cell/cell_model.hpp"
#include "safecell/cspace/cspace_grid.hpp"
#include "safecell/geometry/shape.hpp"

namespace safecell {

struct CoverageOptions {
  double step_m = 0.1;         // floor grid spacing
  double body_radius_m = 0.3;  // the person-sized cylinder
  std::vector<double> body_heights_m{0.4, 2.0};
  double wall_clearance_m = 0.3;  // positions at least this far inside the walls
};

struct FloorCoverage {
  double step_m = 0.1;
  double body_radius_m = 0.3;
  Eigen::Vector2d first_m = Eigen::Vector2d::Zero();  // the position of column 0, row 0
  int columns = 0;
  int rows = 0;
  // Per position (row * columns + column): the cameras that see the body there at every height;
  // -1 where it cannot stand (it would be inside a static obstacle).
  std::vector<int> cameras_seeing;
  int camera_count = 0;
  int camera_threshold = 1;
  double reach_m = 0.0;  // how far the robot reaches from its base axis (l_1 of the grid)

  [[nodiscard]] Eigen::Vector2d position_m(int column, int row) const {
    return first_m + step_m * Eigen::Vector2d(column, row);
  }
  // The index of a position in cameras_seeing.
  [[nodiscard]] std::size_t index(int column, int row) const {
    return static_cast<std::size_t>(row) * static_cast<std::size_t>(columns) +
           static_cast<std::size_t>(column);
  }
  [[nodiscard]] int at(int column, int row) const { return cameras_seeing[index(column, row)]; }
  // A position where a person can stand and fewer than camera_threshold cameras see them.
  [[nodiscard]] bool blind(int column, int row) const {
    const int seeing = at(column, row);
    return seeing >= 0 && seeing < camera_threshold;
  }
  // Positions from which a person's body reaches into the robot's reach (centre within
  // reach_m + body_radius_m of the base axis), and how many of them are blind.
  [[nodiscard]] std::size_t reach_positions() const;
  [[nodiscard]] std::size_t reach_blind_positions() const;
  [[nodiscard]] double reach_blind_share() const;
};

// progress(positions done, positions). Throws std::invalid_argument for a cell without cameras
// or absurd options (a step outside 0.02..1 m, a radius outside 0.05..1 m, heights outside
// 0.1..3 m).
[[nodiscard]] FloorCoverage floor_coverage(
    const CellModel& cell, const CspaceGrid& grid, const CoverageOptions& options = {},
    const std::function<void(std::size_t, std::size_t)>& progress = {});

// Where a person standing at a blind position can be: per run of blind positions along a row, a
// box over the runs' positions grown by the body's radius, 2 m high. The tables forbid every cell
// whose envelope reaches into one, as for a static obstacle.
[[nodiscard]] std::vector<PlacedShape> blind_spot_volumes(const FloorCoverage& coverage);

// The cell the tables are built from: `cell` with the blind-spot volumes as further static
// obstacles (they enter the tables' fingerprint as obstacles do). Only for the tables: the
// simulated cell and the ground truth keep the real obstacles.
[[nodiscard]] CellModel with_blind_spots_forbidden(const CellModel& cell,
                                                   const FloorCoverage& coverage);

}  // namespace safecell
