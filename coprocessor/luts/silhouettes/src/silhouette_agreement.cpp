#include "safecell/silhouettes/silhouette_agreement.hpp"

#include <stdexcept>

namespace safecell {

double CameraAgreement::coverage() const {
  return recorded_cells == 0
             ? 1.0
             : static_cast<double>(inside_model) / static_cast<double>(recorded_cells);
}

double CameraAgreement::fill() const {
  return model_cells == 0 ? 0.0
                          : static_cast<double>(recorded_cells) / static_cast<double>(model_cells);
}

std::vector<CameraAgreement> compare_with_model(const CellModel& cell, const CspaceGrid& grid,
                                                const RecordedSilhouettes& recording,
                                                const RobotSilhouettes& model,
                                                double min_coverage) {
  if (!(min_coverage >= 0.0 && min_coverage <= 1.0)) {
    throw std::invalid_argument("minimum coverage must be within 0..1");
  }
  if (model.camera_count() != recording.camera_count() ||
      cell.cameras.size() != recording.camera_count()) {
    throw std::invalid_argument("recorded and model silhouettes of different cameras");
  }
  std::vector<CameraAgreement> agreement(recording.camera_count());
  for (std::size_t camera = 0; camera < agreement.size(); ++camera) {
    agreement[camera].camera = cell.cameras[camera].name();
  }
  FeatureMask silhouette(cell.feature_grid);
  FeatureMask inside(cell.feature_grid);
  for (std::size_t key = 0; key < recording.key_count(); ++key) {
    const std::vector<double> q = recording.configuration(key, 0);
    JointAngles angles;
    for (std::size_t j = 0; j < q.size(); ++j) angles.rad[j] = q[j];
    const CellIndex key_cell = grid.cell_containing(angles).value();
    for (std::size_t camera = 0; camera < agreement.size(); ++camera) {
      const FeatureMask& seen = recording.key_mask(key, camera);
      const std::size_t seen_cells = seen.count();
      if (seen_cells == 0) continue;
      silhouette.clear();
      model.add_silhouette(key_cell, camera, silhouette);
      inside = seen;
      inside &= silhouette;
      CameraAgreement& entry = agreement[camera];
      ++entry.keys;
      entry.recorded_cells += seen_cells;
      entry.inside_model += inside.count();
      entry.model_cells += silhouette.count();
    }
  }
  for (auto& entry : agreement) entry.flagged = entry.coverage() < min_coverage;
  return agreement;
}

}  // namespace safecell
