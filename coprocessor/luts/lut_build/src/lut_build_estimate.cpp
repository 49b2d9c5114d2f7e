#include "safecell/lut_build/lut_build_estimate.hpp"

#include <algorithm>
#include <chrono>
#include <thread>
#include <vector>

#include "safecell/features/feature_mask.hpp"

namespace safecell {
namespace {

// A build's peak memory per C-space cell: 7.1 GB for the 6 cm grid's 16.5 M cells
// (docs/validation.md), rounded up.
constexpr double kBuildBytesPerCell = 450.0;
// The silhouettes' share of a build's time (the default cell: 88.5 of 92.2 s; the rest is LUT-2's
// inversion and the static obstacles).
constexpr double kSilhouetteShare = 0.96;
// Per part, this many runs of consecutive cells, evenly spread: the build draws cells in order
// and reuses a line's balls along joint 0, so runs cost what the build's cells cost.
constexpr std::uint64_t kRuns = 4;
constexpr std::uint64_t kRunCells = 64;

}  // namespace

double lut_build_peak_bytes(const CspaceGrid& grid) {
  return kBuildBytesPerCell * static_cast<double>(grid.cell_count());
}

LutBuildEstimate estimate_model_lut_build(const CellModel& cell, const CspaceGrid& grid,
                                          const ModelLutOptions& options) {
  // The build makes the same object first: its time is part of the build's (on a small grid, most
  // of it).
  const auto made = std::chrono::steady_clock::now();
  const ModelSilhouettes silhouettes(cell, grid, options);
  const double setup_s =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - made).count();
  LutBuildEstimate estimate;
  estimate.cells = grid.cell_count();
  estimate.peak_bytes = lut_build_peak_bytes(grid);
  estimate.threads =
      options.threads != 0 ? options.threads : std::max(1U, std::thread::hardware_concurrency());
  std::vector<FeatureMask> masks(silhouettes.camera_count(), FeatureMask(cell.feature_grid));
  double seconds_one_thread = 0.0;
  for (std::size_t part = 0; part < silhouettes.parts().size(); ++part) {
    // As build_model_luts: a part is drawn for the cells of its last body's joints only.
    const std::uint64_t drawn =
        silhouettes.envelope().prefix_count(silhouettes.parts()[part].end_body - 1);
    const std::uint64_t run_cells = std::min(kRunCells, drawn);
    const std::uint64_t runs = std::min(kRuns, drawn / run_cells);
    const auto start = std::chrono::steady_clock::now();
    for (std::uint64_t run = 0; run < runs; ++run) {
      const std::uint64_t first = run * (drawn / runs);
      for (std::uint64_t c = first; c < first + run_cells; ++c) {
        for (FeatureMask& mask : masks) mask.clear();
        silhouettes.add_part_silhouettes(static_cast<CellIndex>(c), part, masks.data());
      }
    }
    const double spent =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    const std::uint64_t sampled = runs * run_cells;
    estimate.drawn_cells += drawn;
    estimate.sampled_cells += sampled;
    seconds_one_thread += spent / static_cast<double>(sampled) * static_cast<double>(drawn);
  }
  estimate.seconds = setup_s + seconds_one_thread / kSilhouetteShare / estimate.threads;
  return estimate;
}

}  // namespace safecell
