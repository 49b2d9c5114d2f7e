#pragma once
// Model-mode tables built once and kept: a cache folder holds one LUT file per fingerprint, so a
// changed robot, camera, grid or setting builds anew and an unchanged one loads in milliseconds.

#include <filesystem>
#include <string>

#include <functional>

#include "safecell/lut_build/lut_build_estimate.hpp"
#include "safecell/lut_build/model_luts.hpp"

namespace safecell {

// $SAFECELL_CACHE, else $XDG_CACHE_HOME/safecell, else $HOME/.cache/safecell, else
// ./.safecell-cache.
[[nodiscard]] std::filesystem::path default_lut_cache_folder();

// `<folder>/<fingerprint as 16 hex digits>.sclut`.
[[nodiscard]] std::filesystem::path lut_cache_file(const std::filesystem::path& folder,
                                                   std::uint64_t fingerprint);

struct CachedLuts {
  LutSet set;
  std::filesystem::path file;
  bool built = false;         // false: loaded from the cache
  double build_s = 0.0;       // when built
  std::string note;           // why a cached file was not used, if one was refused
  LutBuildEstimate estimate;  // when built: what was said before
};

// Called with the estimate before a build starts (not when the tables are loaded).
using BuildAnnouncement = std::function<void(const LutBuildEstimate&)>;

// Loads `<folder>/<fingerprint>.sclut`, or builds the tables and stores them there. A cached file
// that is refused (damaged, another version) is rebuilt and replaced; the note says why.
// Before a build, one whose estimated peak memory is beyond 80 % of the machine's is refused
// (InputError naming the figures), and `announce` is told the estimate. Throws FileError when the
// folder cannot be written.
[[nodiscard]] CachedLuts model_luts_cached(const CellModel& cell, const CspaceGrid& grid,
                                           const ModelLutOptions& options,
                                           const std::filesystem::path& folder,
                                           const StagedProgress& progress = {},
                                           const BuildAnnouncement& announce = {});

}  // namespace safecell
