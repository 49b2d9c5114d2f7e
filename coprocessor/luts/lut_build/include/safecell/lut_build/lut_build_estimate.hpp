#pragma once
// What a model-mode table build will take, said before it starts: its peak memory from the cell
// count, and its time from a sample of the build's own work drawn on this machine (the
// silhouettes of a few runs of cells of each robot part, which are 96 % of a build).

#include <cstddef>
#include <cstdint>

#include "safecell/cell/cell_model.hpp"
#include "safecell/cspace/cspace_grid.hpp"
#include "safecell/silhouettes/model_silhouettes.hpp"

namespace safecell {

struct LutBuildEstimate {
  std::uint64_t cells = 0;          // C-space cells of the grid
  std::uint64_t drawn_cells = 0;    // cells whose silhouettes the build draws, over the parts
  std::uint64_t sampled_cells = 0;  // of which drawn here to time them
  unsigned threads = 1;             // the build's worker threads
  double peak_bytes = 0.0;          // while built
  double seconds = 0.0;             // on `threads` threads
};

// The peak memory alone (no sample drawn): for a refusal before anything is built.
[[nodiscard]] double lut_build_peak_bytes(const CspaceGrid& grid);

// Makes the silhouettes' source as the build does and draws 64 cells' silhouettes of each robot
// part on this thread (0.4 s on the default cell). Throws
// std::invalid_argument as ModelSilhouettes does.
[[nodiscard]] LutBuildEstimate estimate_model_lut_build(const CellModel& cell,
                                                        const CspaceGrid& grid,
                                                        const ModelLutOptions& options);

}  // namespace safecell
