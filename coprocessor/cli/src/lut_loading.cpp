#include "lut_loading.hpp"

#include <iostream>

#include "progress_bar.hpp"

namespace safecell {
namespace {

constexpr const char* kStages[kLutBuildStages] = {"building LUT-1 silhouettes", "building LUT-2",
                                                  "static obstacles"};

}  // namespace

CachedLuts cell_luts(const CellModel& cell, const CspaceGrid& grid, const ModelLutOptions& options,
                     const std::string& cache_folder, std::ostream& err) {
  ProgressBar bar(err, &err == &std::cerr && ProgressBar::stderr_is_terminal());
  CachedLuts luts = model_luts_cached(
      cell, grid, options,
      cache_folder.empty() ? default_lut_cache_folder() : std::filesystem::path(cache_folder),
      [&bar](int stage, double fraction) { bar.update(kStages[stage], fraction); });
  bar.finish();
  if (!luts.note.empty()) err << luts.note << '\n';
  if (luts.built)
    err << "look-up tables built in " << luts.build_s << " s: " << luts.file.string() << '\n';
  return luts;
}

}  // namespace safecell
