#pragma once
// What the model-mode and recorded-mode builds share: the stages of a build for a progress bar,
// LUT-1 of every camera from a source of silhouettes, and LUT-2 (with its block levels) of every
// camera from its LUT-1.

#include <functional>
#include <vector>

#include "safecell/cell/cell_model.hpp"
#include "safecell/cspace/cspace_grid.hpp"
#include "safecell/lut_build/cell_table_builder.hpp"
#include "safecell/tables/lut_set.hpp"

namespace safecell {

// Stage 0 silhouettes (LUT-1), 1 inversion (LUT-2), 2 static obstacles.
inline constexpr int kLutBuildStages = 3;
using StagedProgress = std::function<void(int stage, double fraction_done)>;

// The callback of one stage (empty when `progress` is).
[[nodiscard]] ProgressCallback stage_progress(const StagedProgress& progress, int stage);

// LUT-1 of every robot part in every camera of the cell (stage 0) for C-space cells
// 0..cell_count-1 (the grid's cell_count(), or fewer: repeat_cells), part-major: table
// part * cameras + camera.
[[nodiscard]] std::vector<CellToPixelsTable> build_cell_tables(
    const CellModel& cell, std::uint32_t cell_count, std::size_t part_count,
    const CellSilhouettes& silhouettes, unsigned threads, const StagedProgress& progress);

// The set's cameras: LUT-2 of each part from its LUT-1 (stage 1), the tables as
// build_cell_tables() orders them. keep_cell_tables: whether LUT-1 stays in the set (recorded
// mode, one part only) or is dropped (model mode computes it again when needed).
[[nodiscard]] std::vector<CameraLuts> invert_cell_tables(const CellModel& cell,
                                                         const CspaceGrid& grid,
                                                         std::size_t part_count,
                                                         std::vector<CellToPixelsTable> cell_tables,
                                                         bool keep_cell_tables, unsigned threads,
                                                         const StagedProgress& progress);

}  // namespace safecell
