#include "safecell/lut_build/lut_build_stages.hpp"

#include "safecell/lut_build/pixel_table_builder.hpp"

#include <stdexcept>
#include <string>

namespace safecell {

ProgressCallback stage_progress(const StagedProgress& progress, int stage) {
  if (!progress) return {};
  return [&progress, stage](double fraction) { progress(stage, fraction); };
}

std::vector<CellToPixelsTable> build_cell_tables(const CellModel& cell, std::uint32_t cell_count,
                                                 std::size_t part_count,
                                                 const CellSilhouettes& silhouettes,
                                                 unsigned threads, const StagedProgress& progress) {
  CellTableBuild build;
  build.cell_count = cell_count;
  build.table_count = part_count * cell.cameras.size();
  build.columns = cell.feature_grid.columns();
  build.rows = cell.feature_grid.rows();
  build.threads = threads;
  return build_cell_to_pixels_tables(build, silhouettes, stage_progress(progress, 0));
}

std::vector<CameraLuts> invert_cell_tables(const CellModel& cell, const CspaceGrid& grid,
                                           std::size_t part_count,
                                           std::vector<CellToPixelsTable> cell_tables,
                                           bool keep_cell_tables, unsigned threads,
                                           const StagedProgress& progress) {
  const std::size_t cameras = cell.cameras.size();
  if (cell_tables.size() != part_count * cameras || (keep_cell_tables && part_count != 1)) {
    throw std::invalid_argument(std::to_string(cell_tables.size()) + " LUT-1 tables for " +
                                std::to_string(part_count) + " parts and " +
                                std::to_string(cameras) + " cameras");
  }
  PixelTableBuild build;
  build.threads = threads;
  const auto tables = static_cast<double>(cell_tables.size());
  std::vector<CameraLuts> luts(cameras);
  for (std::size_t camera = 0; camera < cameras; ++camera) {
    luts[camera].camera = cell.cameras[camera].name();
  }
  for (std::size_t part = 0; part < part_count; ++part) {
    for (std::size_t camera = 0; camera < cameras; ++camera) {
      const std::size_t table = part * cameras + camera;
      const ProgressCallback inversion = [&progress, table, tables](double fraction) {
        if (progress) progress(1, (static_cast<double>(table) + fraction) / tables);
      };
      luts[camera].parts.push_back(
          build_pixel_to_cells_tables(cell_tables[table], grid, build, inversion));
      if (keep_cell_tables) {
        luts[camera].cell_to_pixels = std::move(cell_tables[table]);
      } else {
        cell_tables[table] = CellToPixelsTable{};  // free it early
      }
    }
  }
  return luts;
}

}  // namespace safecell
