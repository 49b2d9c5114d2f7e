#include "service_setup.hpp"

namespace safecell {

FusionSettings service_fusion_settings(const CellModel& cell, double sync_error_s) {
  FusionSettings fusion;
  fusion.camera_threshold = cell.camera_threshold;
  fusion.sync_error_s = sync_error_s;
  return fusion;
}

}  // namespace safecell
