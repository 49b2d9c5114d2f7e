#pragma once
// Model mode of the implicit calibration (paper §4.1, DESIGN.md §3): the look-up tables computed
// from the robot model and the camera calibrations, with no robot moved. For each C-space cell
// the cell's envelope (every configuration inside it) is projected into every camera.

#include "safecell/cell/cell_model.hpp"
#include "safecell/cspace/cspace_grid.hpp"
#include "safecell/lut/lut_set.hpp"
#include "safecell/lut/parallel_chunks.hpp"

namespace safecell {

struct ModelLutOptions {
  double ball_radius_m = 0.06;  // size of the balls that cover the robot's surface
  double padding_m = 0.02;      // added all round, for calibration and model error
  unsigned threads = 0;         // 0: one per hardware thread
};

// The stages of a build, for a progress bar: stage 0 silhouettes (LUT-1), 1 inversion (LUT-2),
// 2 static obstacles.
using StagedProgress = std::function<void(int stage, double fraction_done)>;

// The fingerprint the set would carry (see LutSet::fingerprint).
[[nodiscard]] std::uint64_t model_lut_fingerprint(const CellModel& cell, const CspaceGrid& grid,
                                                  const ModelLutOptions& options);

// Throws std::invalid_argument when the cell has no robot model or no camera, or for absurd
// options.
[[nodiscard]] LutSet build_model_luts(const CellModel& cell, const CspaceGrid& grid,
                                      const ModelLutOptions& options = {},
                                      const StagedProgress& progress = {});

}  // namespace safecell
