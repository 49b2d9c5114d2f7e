#include "safecell/lut_build/lut_build_stages.hpp"

#include "safecell/lut_build/pixel_table_builder.hpp"

namespace safecell {

ProgressCallback stage_progress(const StagedProgress& progress, int stage) {
  if (!progress) return {};
  return [&progress, stage](double fraction) { progress(stage, fraction); };
}

std::vector<CellToPixelsTable> build_cell_tables(const CellModel& cell, const CspaceGrid& grid,
                                                 const CellSilhouettes& silhouettes,
                                                 unsigned threads, const StagedProgress& progress) {
  CellTableBuild build;
  build.cell_count = grid.cell_count();
  build.camera_count = cell.cameras.size();
  build.columns = cell.feature_grid.columns();
  build.rows = cell.feature_grid.rows();
  build.threads = threads;
  return build_cell_to_pixels_tables(build, silhouettes, stage_progress(progress, 0));
}

std::vector<CameraLuts> invert_cell_tables(const CellModel& cell, const CspaceGrid& grid,
                                           std::vector<CellToPixelsTable> cell_tables,
                                           bool keep_cell_tables, unsigned threads,
                                           const StagedProgress& progress) {
  PixelTableBuild build;
  build.threads = threads;
  const auto cameras = static_cast<double>(cell.cameras.size());
  std::vector<CameraLuts> luts;
  for (std::size_t camera = 0; camera < cell.cameras.size(); ++camera) {
    const ProgressCallback inversion = [&progress, camera, cameras](double fraction) {
      if (progress) progress(1, (static_cast<double>(camera) + fraction) / cameras);
    };
    PixelTables pixel_tables =
        build_pixel_to_cells_tables(cell_tables[camera], grid, build, inversion);
    const std::uint64_t pairs = cell_tables[camera].covered_pairs();
    luts.push_back(
        CameraLuts{cell.cameras[camera].name(),
                   keep_cell_tables ? std::move(cell_tables[camera]) : CellToPixelsTable{},
                   std::move(pixel_tables.pixels), std::move(pixel_tables.blocks), pairs,
                   std::move(pixel_tables.differences)});
    if (!keep_cell_tables) cell_tables[camera] = CellToPixelsTable{};  // free it early
  }
  return luts;
}

}  // namespace safecell
