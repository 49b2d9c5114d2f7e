#pragma once
// The demo's sequence of forbidden maps (its scenario, sim/demo_scenario.hpp, through the real
// sensing pipeline) on the coarse default cell, computed once per test program.

#include <vector>

#include "safecell/cspace/cspace_grid.hpp"
#include "safecell/lut/cell_set.hpp"

namespace safecell::test {

struct DemoMaps {
  CspaceGrid grid;
  std::vector<CellSet> maps;  // one per camera cycle, 30 per second
};

const DemoMaps& demo_maps();

}  // namespace safecell::test
