#include "safecell/pipeline/cell_fusion_settings.hpp"

namespace safecell {

FusionSettings cell_fusion_settings(const CellModel& cell) {
  FusionSettings fusion;
  fusion.camera_threshold = cell.camera_threshold;
  fusion.occlusion_reach = cell.occlusion_reach_cells.value_or(kDefaultOcclusionReach);
  return fusion;
}

}  // namespace safecell
