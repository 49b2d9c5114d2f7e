#include "safecell/lut_files/lut_cache.hpp"

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <system_error>

#include "safecell/files/atomic_write.hpp"
#include "safecell/lut_files/lut_file.hpp"

namespace safecell {

std::filesystem::path default_lut_cache_folder() {
  if (const char* folder = std::getenv("SAFECELL_CACHE"); folder != nullptr && *folder != '\0') {
    return folder;
  }
  if (const char* xdg = std::getenv("XDG_CACHE_HOME"); xdg != nullptr && *xdg != '\0') {
    return std::filesystem::path(xdg) / "safecell";
  }
  if (const char* home = std::getenv("HOME"); home != nullptr && *home != '\0') {
    return std::filesystem::path(home) / ".cache" / "safecell";
  }
  return ".safecell-cache";
}

std::filesystem::path lut_cache_file(const std::filesystem::path& folder,
                                     std::uint64_t fingerprint) {
  char name[32];
  std::snprintf(name, sizeof name, "%016llx.sclut", static_cast<unsigned long long>(fingerprint));
  return folder / name;
}

CachedLuts model_luts_cached(const CellModel& cell, const CspaceGrid& grid,
                             const ModelLutOptions& options, const std::filesystem::path& folder,
                             const StagedProgress& progress) {
  const std::uint64_t fingerprint = model_lut_fingerprint(cell, grid, options);
  CachedLuts result;
  result.file = lut_cache_file(folder, fingerprint);
  std::error_code error;
  if (std::filesystem::exists(result.file, error)) {
    try {
      result.set = load_lut_file(result.file, grid, fingerprint);
      return result;
    } catch (const LutFileError& refused) {
      result.note = std::string("rebuilt: ") + refused.what();
    }
  }
  std::filesystem::create_directories(folder, error);
  if (error) throw FileError(folder, "cannot create the LUT cache folder: " + error.message());
  const auto start = std::chrono::steady_clock::now();
  result.set = build_model_luts(cell, grid, options, progress);
  result.build_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  result.built = true;
  write_lut_file(result.file, result.set);
  return result;
}

}  // namespace safecell
