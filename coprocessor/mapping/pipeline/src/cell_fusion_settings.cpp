#include "safecell/pipeline/cell_fusion_settings.hpp"

namespace safecell {

FusionSettings cell_fusion_settings(const CellModel& cell) {
  FusionSettings fusion;
  fusion.camera_threshold = cell.camera_threshold;
  fusion.occlusion_reach = cell.occlusion_reach_cells.value_or(kDefaultOcclusionReach);
  return fusion;
}

std::string vote_warning(const CellModel& cell) {
  const FusionSettings fusion = cell_fusion_settings(cell);
  if (fusion.camera_threshold < 3 || fusion.occlusion_reach >= kReachValidatedAtThresholdThree) {
    return {};
  }
  return cell.config.source + ": camera_threshold " + std::to_string(fusion.camera_threshold) +
         " with occlusion_reach_cells " + std::to_string(fusion.occlusion_reach) +
         (cell.occlusion_reach_cells ? "" : " (unset: the default)") +
         " - a person the arm hides from all but two cameras may not be seen by enough of them; "
         "the validation missed collisions so at reach 3 and none at " +
         std::to_string(kReachValidatedAtThresholdThree) +
         " (set occlusion_reach_cells: " + std::to_string(kReachValidatedAtThresholdThree) + ")";
}

}  // namespace safecell
