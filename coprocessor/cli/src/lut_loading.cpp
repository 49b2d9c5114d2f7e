#include "lut_loading.hpp"

#include <iostream>
#include <optional>

#include "progress_bar.hpp"
#include "safecell/validation/floor_coverage.hpp"

namespace safecell {
namespace {

constexpr const char* kStages[kLutBuildStages] = {"building LUT-1 silhouettes", "building LUT-2",
                                                  "static obstacles"};

}  // namespace

CachedLuts cell_luts(const CellModel& cell, const CspaceGrid& grid, const ModelLutOptions& options,
                     const std::string& cache_folder, std::ostream& err) {
  std::optional<CellModel> with_blind_spots;
  if (!cell.config.forbid_blind_spots) {
    err << "warning: " << cell.config.source
        << ": blind_spots: allow - people the cameras cannot see may stand where the robot "
           "reaches (safecell cell coverage shows where)\n";
  } else {
    CoverageOptions coverage_options;
    coverage_options.step_m = kBlindSpotStep_m;
    const FloorCoverage coverage = floor_coverage(cell, grid, coverage_options);
    CellModel forbidding = with_blind_spots_forbidden(cell, coverage);
    if (forbidding.obstacles.size() > cell.obstacles.size()) {
      with_blind_spots = std::move(forbidding);
      err << "blind spots: " << coverage.reach_blind_positions()
          << " floor positions within the robot's reach are seen by fewer than "
          << coverage.camera_threshold << " cameras; the cells reaching there are forbidden\n";
    }
  }
  ProgressBar bar(err, &err == &std::cerr && ProgressBar::stderr_is_terminal());
  CachedLuts luts = model_luts_cached(
      with_blind_spots ? *with_blind_spots : cell, grid, options,
      cache_folder.empty() ? default_lut_cache_folder() : std::filesystem::path(cache_folder),
      [&bar](int stage, double fraction) { bar.update(kStages[stage], fraction); });
  bar.finish();
  if (!luts.note.empty()) err << luts.note << '\n';
  if (luts.built)
    err << "look-up tables built in " << luts.build_s << " s: " << luts.file.string() << '\n';
  return luts;
}

}  // namespace safecell
