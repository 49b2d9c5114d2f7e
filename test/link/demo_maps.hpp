#pragma once
// The demo's sequence of forbidden maps (its scenario, sim/demo_scenario.hpp, through the real
// sensing pipeline) on the coarse default cell, computed once per test program.

#include <vector>

#include "safecell/cellsets/cell_set.hpp"
#include "safecell/cspace/cspace_grid.hpp"

namespace safecell::test {

struct DemoMaps {
  CspaceGrid grid;
  std::vector<CellSet> maps;  // one per camera cycle, 30 per second
};

const DemoMaps& demo_maps();

}  // namespace safecell::test
