#pragma once
// Writes forbidden maps with their grid in the file format the controller's benchmark program
// reads (controller/host/bench/map_sequence_file.hpp has the layout), so `safecell bench` can run
// the controller's figures on the demo's maps without either side linking the other's code.

#include <string>
#include <vector>

#include "safecell/cellsets/cell_set.hpp"
#include "safecell/cspace/cspace_grid.hpp"

namespace safecell {

// Atomic: a temporary file renamed into place. Throws std::runtime_error naming the path.
void write_map_sequence_file(const std::string& path, const CspaceGrid& grid,
                             const std::vector<CellSet>& maps);

// The demo's maps on the default cell into `path` (builds the tables on first use).
void write_default_cell_demo_maps(const std::string& path);

}  // namespace safecell
