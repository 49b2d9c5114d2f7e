#pragma once
// The model-mode tables of a cell for the commands that run the pipeline: from the cache, built
// with a progress bar on the first run. Private to the CLI.

#include <ostream>
#include <string>

#include "safecell/lut/lut_cache.hpp"

namespace safecell {

// The floor grid the tables' blind spots are found on: coarser than `cell coverage`'s picture,
// so that loading cached tables stays quick; the volumes grow by half of it.
inline constexpr double kBlindSpotStep_m = 0.2;

// cache_folder: empty for the default. Messages (build, rebuild reason, blind spots) go to
// `err`. Unless the cell allows them (with a warning), blind spots are forbidden: the tables are
// built with their volumes as static obstacles (floor_coverage.hpp, at kBlindSpotStep_m).
CachedLuts cell_luts(const CellModel& cell, const CspaceGrid& grid, const ModelLutOptions& options,
                     const std::string& cache_folder, std::ostream& err);

}  // namespace safecell
