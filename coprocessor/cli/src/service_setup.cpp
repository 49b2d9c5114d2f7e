#include "service_setup.hpp"

#include "safecell/pipeline/cell_fusion_settings.hpp"

namespace safecell {

FusionSettings service_fusion_settings(const CellModel& cell, double sync_error_s) {
  FusionSettings fusion = cell_fusion_settings(cell);
  fusion.sync_error_s = sync_error_s;
  return fusion;
}

}  // namespace safecell
