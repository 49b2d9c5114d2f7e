#include "default_cell_tables.hpp"

#include <chrono>

#include "safecell/cell/cell_grid.hpp"
#include "safecell/cell/default_cell.hpp"
#include "safecell/lut_build/model_luts.hpp"
#include "safecell/sim/demo_scenario.hpp"
#include "safecell/validation/demo_maps.hpp"

namespace safecell {
namespace {

LutSet timed_build(const CellModel& cell, const CspaceGrid& grid, double& seconds) {
  const auto start = std::chrono::steady_clock::now();
  LutSet luts = build_model_luts(cell, grid);
  seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return luts;
}

}  // namespace

DefaultCellTables::DefaultCellTables()
    : cell(load_cell_model(default_cell())),
      grid(make_grid(cell.config)),
      luts(timed_build(cell, grid, build_s)),
      silhouettes(cell, grid, ModelLutOptions{}, CellDrawing::kWholeCells) {}

const DefaultCellTables& default_cell_tables() {
  static const DefaultCellTables tables;
  return tables;
}

const std::vector<CellSet>& default_cell_demo_maps() {
  static const std::vector<CellSet> maps = [] {
    const DefaultCellTables& tables = default_cell_tables();
    return demo_map_sequence(tables.cell, tables.grid, tables.luts, tables.silhouettes,
                             kDemoHumanEnters_s, 30);
  }();
  return maps;
}

}  // namespace safecell
