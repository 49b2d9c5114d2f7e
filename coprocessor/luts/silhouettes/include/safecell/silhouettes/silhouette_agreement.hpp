#pragma once
// Recorded against model silhouettes, per camera: the check that catches a camera whose
// calibration is off, which otherwise shows as the robot seen as its own obstacle (its real
// pixels outside the silhouette that robot removal takes away).
//
// For every key of a recording, the feature cells the camera saw of the robot (undilated) should
// lie inside the model's silhouette of the key's cell, which holds the robot anywhere in that
// cell. coverage = the share that does; a camera below min_coverage is flagged.

#include <cstdint>
#include <string>
#include <vector>

#include "safecell/cell/cell_model.hpp"
#include "safecell/cspace/cspace_grid.hpp"
#include "safecell/silhouettes/recorded_silhouettes.hpp"
#include "safecell/silhouettes/robot_silhouettes.hpp"

namespace safecell {

struct CameraAgreement {
  std::string camera;
  std::size_t keys = 0;              // keys whose recording saw the robot at all
  std::uint64_t recorded_cells = 0;  // feature cells seen, summed over the keys
  std::uint64_t inside_model = 0;    // of which inside the model's silhouette
  std::uint64_t model_cells = 0;     // the model's silhouettes, summed over the same keys
  bool flagged = false;

  // inside_model / recorded_cells (1 when nothing was recorded).
  [[nodiscard]] double coverage() const;
  // recorded_cells / model_cells: how much of the conservative silhouette the robot fills.
  [[nodiscard]] double fill() const;
};

inline constexpr double kDefaultMinCoverage = 0.95;

// Precondition: recording.recorded(); model of the same cameras. Throws std::invalid_argument
// for min_coverage outside 0..1 or camera counts that differ.
[[nodiscard]] std::vector<CameraAgreement> compare_with_model(
    const CellModel& cell, const CspaceGrid& grid, const RecordedSilhouettes& recording,
    const RobotSilhouettes& model, double min_coverage = kDefaultMinCoverage);

}  // namespace safecell
