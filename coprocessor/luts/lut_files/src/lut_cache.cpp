#include "safecell/lut_files/lut_cache.hpp"

#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <sstream>
#include <system_error>

#include "safecell/errors/input_error.hpp"
#include "safecell/files/atomic_write.hpp"
#include "safecell/lut_files/lut_file.hpp"

namespace safecell {
namespace {

// A build that needs more than most of the machine's memory is refused before it starts (a cell
// of m_max_m 0.01 ended in std::bad_alloc, exit 70).
constexpr double kUsableMemoryShare = 0.8;

void check_build_fits_the_machine(const LutBuildEstimate& estimate) {
  const long pages = ::sysconf(_SC_PHYS_PAGES);
  const long page_bytes = ::sysconf(_SC_PAGESIZE);
  if (pages <= 0 || page_bytes <= 0) return;  // unknown: the build will tell
  const double have = static_cast<double>(pages) * static_cast<double>(page_bytes);
  if (estimate.peak_bytes <= kUsableMemoryShare * have) return;
  std::ostringstream message;
  message.precision(3);
  message << "the tables of this cell's " << estimate.cells << " C-space cells need about "
          << estimate.peak_bytes / 1e9 << " GB while they are built, this machine has "
          << have / 1e9
          << " GB; raise m_max_m or discretise fewer joints (safecell cell info shows the cells)";
  throw InputError(message.str());
}

// A cell whose cameras cannot outvote the threshold anywhere in the robot's reach protects
// nobody: every camera's tables empty (cameras that see none of the robot's reach, or a pose file
// turned around) built and ran with exit 0.
void check_cameras_see_the_robot(const CellModel& cell, const LutSet& set) {
  if (cell.cameras.empty()) return;
  int seeing = 0;
  std::ostringstream pairs;
  for (std::size_t c = 0; c < set.cameras.size() && c < cell.cameras.size(); ++c) {
    const std::uint64_t covered = set.cameras[c].covered_pairs();
    seeing += covered > 0 ? 1 : 0;
    pairs << (c == 0 ? "" : ", ") << cell.cameras[c].name() << " " << covered;
  }
  if (seeing >= cell.camera_threshold) return;
  throw InputError("only " + std::to_string(seeing) + " of " + std::to_string(cell.cameras.size()) +
                   " cameras see any of the robot's reach (pixel-cell pairs: " + pairs.str() +
                   "), and a cell needs " + std::to_string(cell.camera_threshold) +
                   " to vote: it cannot protect anyone; check the cameras' poses "
                   "(safecell cell coverage)");
}

}  // namespace

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
                             const StagedProgress& progress, const BuildAnnouncement& announce) {
  const std::uint64_t fingerprint = model_lut_fingerprint(cell, grid, options);
  CachedLuts result;
  result.file = lut_cache_file(folder, fingerprint);
  std::error_code error;
  if (std::filesystem::exists(result.file, error)) {
    try {
      result.set = load_lut_file(result.file, grid, fingerprint);
      check_cameras_see_the_robot(cell, result.set);
      return result;
    } catch (const LutFileError& refused) {
      result.note = std::string("rebuilt: ") + refused.what();
    }
  }
  // The memory first: a grid too large for the machine is refused before its sample is drawn.
  LutBuildEstimate estimate;
  estimate.cells = grid.cell_count();
  estimate.peak_bytes = lut_build_peak_bytes(grid);
  check_build_fits_the_machine(estimate);
  estimate = estimate_model_lut_build(cell, grid, options);
  result.estimate = estimate;
  if (announce) announce(estimate);
  std::filesystem::create_directories(folder, error);
  if (error) throw FileError(folder, "cannot create the LUT cache folder: " + error.message());
  const auto start = std::chrono::steady_clock::now();
  result.set = build_model_luts(cell, grid, options, progress);
  result.build_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  result.built = true;
  write_lut_file(result.file, result.set);
  check_cameras_see_the_robot(cell, result.set);
  return result;
}

}  // namespace safecell
