#pragma once
// The default cell with its model-mode tables, built once per process (before any timing) and
// shared by the fusion and link benchmarks.

#include <vector>

#include "safecell/cell/cell_model.hpp"
#include "safecell/cellsets/cell_set.hpp"
#include "safecell/cspace/cspace_grid.hpp"
#include "safecell/silhouettes/model_silhouettes.hpp"
#include "safecell/tables/lut_set.hpp"

namespace safecell {

struct DefaultCellTables {
  CellModel cell;
  CspaceGrid grid;
  double build_s = 0.0;  // to build the tables
  LutSet luts;
  ModelSilhouettes silhouettes;  // robot removal's: whole cells (CellDrawing::kWholeCells)

  DefaultCellTables();
};

const DefaultCellTables& default_cell_tables();

// The demo's forbidden maps on the default cell: 1 s from when the person walks in, at 30 frames
// per second, through the real pipeline (built once per process).
const std::vector<CellSet>& default_cell_demo_maps();

}  // namespace safecell
