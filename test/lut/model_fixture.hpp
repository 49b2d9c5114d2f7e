#pragma once
// The default cell on a coarse grid (m_max 0.4 m, joints 1-3 discretised, a few thousand cells), so
// that the model tests can afford to check every cell; and random configurations inside a cell.

#include <optional>
#include <random>
#include <vector>

#include "safecell/cell/cell_grid.hpp"
#include "safecell/cell/cell_model.hpp"
#include "safecell/cell/default_cell.hpp"
#include "safecell/cspace/cspace_grid.hpp"
#include "safecell/lut_build/model_luts.hpp"

namespace safecell::test {

inline CellConfig coarse_default_config() {
  CellConfig config = default_cell();
  config.m_max_m = 0.4;
  config.joints.at(3).discretised = false;  // its l_i (0.12 m) is below m_max / 2
  config.envelope_max_move_m.reset();       // whole cells: the tables fast to build
  return config;
}

inline CellModel coarse_default_cell() { return load_cell_model(coarse_default_config()); }

inline ModelLutOptions options_with(std::optional<PartSplit> parts) {
  ModelLutOptions options;
  options.parts = parts;
  return options;
}

// The coarse default cell with its model-mode tables and silhouettes, the cameras voting on the
// robot parts of `parts` (unset: the cell's).
struct CoarseTables {
  explicit CoarseTables(std::optional<PartSplit> parts = std::nullopt)
      : options(options_with(parts)) {}
  ModelLutOptions options;
  CellModel cell = coarse_default_cell();
  CspaceGrid grid = make_grid(cell.config);
  LutSet luts = build_model_luts(cell, grid, options);
  ModelSilhouettes silhouettes{cell, grid, options};
};

// A configuration anywhere inside the cell (joints kept whole: anywhere in their range).
inline std::vector<double> configuration_in(const CspaceGrid& grid, CellIndex cell,
                                            std::mt19937_64& rng) {
  const GridCoords coords = grid.coords_of(cell).value();
  std::vector<double> q(grid.joint_count());
  for (std::uint32_t j = 0; j < grid.joint_count(); ++j) {
    const AngleInterval bounds = grid.cell_bounds(coords, j).value();
    q[j] = std::uniform_real_distribution<double>(bounds.lo_rad, bounds.hi_rad)(rng);
  }
  return q;
}

inline CellIndex cell_of(const CspaceGrid& grid, const std::vector<double>& q) {
  JointAngles angles;
  for (std::size_t j = 0; j < q.size(); ++j) angles.rad[j] = q[j];
  return grid.cell_containing(angles).value();
}

}  // namespace safecell::test
