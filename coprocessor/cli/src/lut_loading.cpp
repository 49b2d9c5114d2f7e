#include "lut_loading.hpp"

#include <iostream>

#include "progress_bar.hpp"
#include "safecell/cell/entry_zones.hpp"
#include "safecell/cli/text_table.hpp"
#include "safecell/pipeline/cell_fusion_settings.hpp"
#include "safecell/validation/floor_coverage.hpp"

namespace safecell {
namespace {

constexpr const char* kStages[kLutBuildStages] = {"building LUT-1 silhouettes", "building LUT-2",
                                                  "static obstacles"};

}  // namespace

CellModel tables_cell(const CellModel& cell, const CspaceGrid& grid, std::ostream& err) {
  if (const std::string warning = vote_warning(cell); !warning.empty()) {
    err << "warning: " << warning << '\n';
  }
  CellModel tables = cell;
  if (!cell.config.forbid_blind_spots) {
    err << "warning: " << cell.config.source
        << ": blind_spots: allow - people the cameras cannot see may stand where the robot "
           "reaches (safecell cell coverage shows where)\n";
  } else {
    CoverageOptions coverage_options;
    coverage_options.step_m = kBlindSpotStep_m;
    const FloorCoverage coverage = floor_coverage(cell, grid, coverage_options);
    tables = with_blind_spots_forbidden(cell, coverage);
    if (tables.obstacles.size() > cell.obstacles.size()) {
      err << "blind spots: " << coverage.reach_blind_positions()
          << " floor positions within the robot's reach are seen by fewer than "
          << coverage.camera_threshold << " cameras; the cells reaching there are forbidden\n";
    }
  }
  if (!cell.config.entries) {
    err << "warning: " << cell.config.source
        << ": no entries named - people may step in anywhere along the walls, where the robot "
           "may not have room to stop (name the cell's entries to keep it away from them)\n";
  } else {
    tables = with_entry_zones_forbidden(tables);
    err << "entries: " << cell.config.entries->size() << "; the cells within "
        << separation_distance_m(cell.config.entry_separation)
        << " m of them (the separation distance) are forbidden\n";
  }
  return tables;
}

std::string build_estimate_line(const LutBuildEstimate& estimate, std::size_t cameras) {
  const double minutes = estimate.seconds / 60.0;
  const std::string time = estimate.seconds < 120.0 ? fixed(estimate.seconds, 0) + " s"
                           : minutes < 120.0        ? fixed(minutes, 1) + " min"
                                                    : fixed(minutes / 60.0, 1) + " h";
  return "building the tables of " + grouped(estimate.cells) + " C-space cells (" +
         std::to_string(cameras) + " cameras): about " + fixed(estimate.peak_bytes / 1e6, 0) +
         " MB at the peak, about " + time + " on " + std::to_string(estimate.threads) +
         " threads (timed on " + grouped(estimate.sampled_cells) + " of the " +
         grouped(estimate.drawn_cells) + " cells the build draws)";
}

CachedLuts cell_luts(const CellModel& cell, const CspaceGrid& grid, const ModelLutOptions& options,
                     const std::string& cache_folder, std::ostream& err) {
  const CellModel tables = tables_cell(cell, grid, err);
  ProgressBar bar(err, &err == &std::cerr && ProgressBar::stderr_is_terminal());
  CachedLuts luts = model_luts_cached(
      tables, grid, options,
      cache_folder.empty() ? default_lut_cache_folder() : std::filesystem::path(cache_folder),
      [&bar](int stage, double fraction) { bar.update(kStages[stage], fraction); },
      [&err, &tables](const LutBuildEstimate& estimate) {
        err << build_estimate_line(estimate, tables.cameras.size()) << '\n';
      });
  bar.finish();
  if (!luts.note.empty()) err << luts.note << '\n';
  if (luts.built)
    err << "look-up tables built in " << luts.build_s << " s: " << luts.file.string() << '\n';
  return luts;
}

}  // namespace safecell
