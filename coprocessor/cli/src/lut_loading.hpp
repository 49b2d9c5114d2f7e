#pragma once
// The model-mode tables of a cell for the commands that run the pipeline: from the cache, built
// with a progress bar on the first run. Private to the CLI.

#include <ostream>
#include <string>

#include "safecell/lut/lut_cache.hpp"

namespace safecell {

// cache_folder: empty for the default. Messages (build, rebuild reason) go to `err`.
CachedLuts cell_luts(const CellModel& cell, const CspaceGrid& grid, const ModelLutOptions& options,
                     const std::string& cache_folder, std::ostream& err);

}  // namespace safecell
