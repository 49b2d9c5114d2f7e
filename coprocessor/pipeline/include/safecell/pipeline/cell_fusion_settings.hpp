#pragma once
// The fusion settings a cell file asks for: its camera threshold and occlusion reach, the rest
// (sync error, padding, removal) by default. Every pipeline built from a cell starts here, so
// the service, the demo, the bench and `validate` vote the same way.

#include "safecell/cell/cell_model.hpp"
#include "safecell/fusion/forbidden_map_fusion.hpp"

namespace safecell {

[[nodiscard]] FusionSettings cell_fusion_settings(const CellModel& cell);

}  // namespace safecell
