#pragma once
// The look-up tables of recorded mode: LUT-1 from a recording (recorded_silhouettes.hpp), stored
// in the set since robot removal needs it and it cannot be recomputed; LUT-2 built from it as in
// model mode. The static obstacles still come from the robot model's envelopes: boxes that are
// never seen as the robot cannot be recorded.
//
// The fingerprint is the model set's (grid, robot geometry, cameras, feature grid, obstacles)
// with the recording's options, so that a cell file and the options alone tell whether a stored
// recorded set still fits.

#include "safecell/cell/cell_model.hpp"
#include "safecell/cspace/cspace_grid.hpp"
#include "safecell/lut_build/model_luts.hpp"
#include "safecell/silhouettes/recorded_silhouettes.hpp"
#include "safecell/tables/lut_set.hpp"

namespace safecell {

[[nodiscard]] std::uint64_t recorded_lut_fingerprint(const CellModel& cell, const CspaceGrid& grid,
                                                     const RecordingOptions& options);

// Throws InputError naming the cameras too close for the recording's bound (its
// unbounded_cameras()); before recording, so that no time is spent on a recording that cannot be
// used.
void check_recording_bounded(const RecordedSilhouettes& recording);

// Precondition: recording.recorded(). Throws InputError naming the cameras when
// some are too close for the recording's bound. Progress stages as build_model_luts().
[[nodiscard]] LutSet build_recorded_luts(const CellModel& cell, const CspaceGrid& grid,
                                         const RecordedSilhouettes& recording, unsigned threads = 0,
                                         const StagedProgress& progress = {});

}  // namespace safecell
