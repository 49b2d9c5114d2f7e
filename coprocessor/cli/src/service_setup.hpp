#pragma once
// What the service's pipeline is built with beyond the cell, shared by `safecell run` and
// `safecell replay` (a replay gives the maps the service sent only when its pipeline is built
// the same way). Private to the CLI.

#include "safecell/cell/cell_model.hpp"
#include "safecell/fusion/forbidden_map_fusion.hpp"

namespace safecell {

// The cell's fusion settings (cell_fusion_settings.hpp) with the cameras' exposure allowance (s).
FusionSettings service_fusion_settings(const CellModel& cell, double sync_error_s);

}  // namespace safecell
