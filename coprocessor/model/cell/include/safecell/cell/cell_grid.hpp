#pragma once
// The C-space grid of a cell. All checks of sense live in CspaceGrid::create(); this maps its
// refusal back to the field of the cell file.

#include "safecell/cell/cell_config.hpp"
#include "safecell/cspace/cspace_grid.hpp"

namespace safecell {

// Precondition: a complete cell (see load_cell_model()); std::bad_optional_access otherwise.
GridSpec grid_spec_of(const CellConfig& cell);

// Throws CellError naming the file, line, field and value when the grid cannot be built.
CspaceGrid make_grid(const CellConfig& cell);

}  // namespace safecell
