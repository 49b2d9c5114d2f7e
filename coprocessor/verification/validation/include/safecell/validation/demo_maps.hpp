#pragma once
// The demo's sequence of forbidden maps: its scenario (sim/demo_scenario.hpp) rendered and run
// through the real sensing pipeline, one map per camera cycle. The link's integration test and
// its benchmarks send this sequence.

#include <vector>

#include "safecell/cell/cell_model.hpp"
#include "safecell/cellsets/cell_set.hpp"
#include "safecell/cspace/cspace_grid.hpp"
#include "safecell/silhouettes/robot_silhouettes.hpp"
#include "safecell/tables/lut_set.hpp"

namespace safecell {

// `cycles` maps at `fps` from scenario time first_s.
std::vector<CellSet> demo_map_sequence(const CellModel& cell, const CspaceGrid& grid,
                                       const LutSet& luts, const RobotSilhouettes& silhouettes,
                                       double first_s, int cycles, double fps = 30.0);

}  // namespace safecell
