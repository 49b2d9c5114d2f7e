#pragma once
// Model mode of the implicit calibration (paper §4.1, DESIGN.md §3): the look-up tables computed
// from the robot model and the camera calibrations, with no robot moved. Every C-space cell's
// envelope is projected into every camera (LUT-1, model_silhouettes.hpp), LUT-2 is built from
// that, and the static obstacles are tested against the envelopes.
//
// A model-mode set keeps no LUT-1 table: robot removal computes the one row it needs per cycle
// from the model (ModelSilhouettes), exactly as the build did; the fingerprint ties the two.

#include "safecell/cell/cell_model.hpp"
#include "safecell/cspace/cspace_grid.hpp"
#include "safecell/lut_build/lut_build_stages.hpp"
#include "safecell/silhouettes/model_silhouettes.hpp"
#include "safecell/tables/lut_set.hpp"

namespace safecell {

// The fingerprint the set would carry (see LutSet::fingerprint).
[[nodiscard]] std::uint64_t model_lut_fingerprint(const CellModel& cell, const CspaceGrid& grid,
                                                  const ModelLutOptions& options);

// Throws std::invalid_argument as ModelSilhouettes does.
[[nodiscard]] LutSet build_model_luts(const CellModel& cell, const CspaceGrid& grid,
                                      const ModelLutOptions& options = {},
                                      const StagedProgress& progress = {});

}  // namespace safecell
