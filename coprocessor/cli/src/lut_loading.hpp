#pragma once
// The model-mode tables of a cell for the commands that run the pipeline: from the cache, built
// with a progress bar on the first run. Private to the CLI.

#include <ostream>
#include <string>

#include "safecell/lut_files/lut_cache.hpp"

namespace safecell {

// The floor grid the tables' blind spots are found on: coarser than `cell coverage`'s picture,
// so that loading cached tables stays quick; the volumes grow by half of it.
inline constexpr double kBlindSpotStep_m = 0.2;

// The cell the tables are built from: `cell` with the volumes no robot may reach into as static
// obstacles. Blind spots (floor_coverage.hpp, at kBlindSpotStep_m) unless the cell allows them,
// and the zones within the separation distance of each entry (entry_zones.hpp). What the cell
// leaves open (blind spots allowed, no entries named), and a vote the validation does not cover
// (vote_warning), is a warning on `err`.
CellModel tables_cell(const CellModel& cell, const CspaceGrid& grid, std::ostream& err);

// One line said before a table build: "building the tables of 186,480 C-space cells (4 cameras):
// about 84 MB at the peak, about 1.6 min on 2 threads (timed on 320 of the 1,380,000 cells the
// build draws)".
std::string build_estimate_line(const LutBuildEstimate& estimate, std::size_t cameras);

// cache_folder: empty for the default. Messages (build, rebuild reason, blind spots) go to
// `err`. The tables are those of tables_cell(cell).
CachedLuts cell_luts(const CellModel& cell, const CspaceGrid& grid, const ModelLutOptions& options,
                     const std::string& cache_folder, std::ostream& err);

}  // namespace safecell
