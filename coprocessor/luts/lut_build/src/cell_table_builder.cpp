#include "safecell/lut_build/cell_table_builder.hpp"

#include <limits>
#include <stdexcept>
#include <string>

namespace safecell {
namespace {

constexpr std::size_t kCellsPerChunk = 512;

// What one chunk of cells produced for one table: rectangles per cell, in cell order.
struct ChunkRects {
  std::vector<std::uint32_t> counts;
  std::vector<FeatureRect> rects;
};

}  // namespace

std::vector<CellToPixelsTable> build_cell_to_pixels_tables(const CellTableBuild& build,
                                                           const CellSilhouettes& silhouettes,
                                                           const ProgressCallback& progress) {
  const std::size_t chunks = (build.cell_count + kCellsPerChunk - 1) / kCellsPerChunk;
  // chunk_rects[chunk][table]
  std::vector<std::vector<ChunkRects>> chunk_rects(chunks);
  parallel_chunks(
      build.cell_count, kCellsPerChunk, build.threads,
      [&](std::size_t chunk, std::size_t begin, std::size_t end) {
        std::vector<FeatureMask> masks(build.table_count, FeatureMask(build.columns, build.rows));
        std::vector<ChunkRects> out(build.table_count);
        for (std::size_t cell = begin; cell < end; ++cell) {
          for (auto& mask : masks) mask.clear();
          silhouettes(static_cast<CellIndex>(cell), masks);
          for (std::size_t table = 0; table < build.table_count; ++table) {
            const std::size_t before = out[table].rects.size();
            masks[table].append_rectangles(out[table].rects);
            out[table].counts.push_back(
                static_cast<std::uint32_t>(out[table].rects.size() - before));
          }
        }
        chunk_rects[chunk] = std::move(out);
      },
      progress);

  std::vector<CellToPixelsTable> tables;
  tables.reserve(build.table_count);
  for (std::size_t table = 0; table < build.table_count; ++table) {
    std::vector<std::uint64_t> offsets;
    offsets.reserve(static_cast<std::size_t>(build.cell_count) + 1);
    offsets.push_back(0);
    std::size_t total = 0;
    for (const auto& chunk : chunk_rects) total += chunk[table].rects.size();
    std::vector<FeatureRect> rects;
    rects.reserve(total);
    for (auto& chunk : chunk_rects) {
      for (const std::uint32_t count : chunk[table].counts)
        offsets.push_back(offsets.back() + count);
      rects.insert(rects.end(), chunk[table].rects.begin(), chunk[table].rects.end());
      chunk[table] = ChunkRects{};
    }
    tables.emplace_back(build.columns, build.rows, std::move(offsets), std::move(rects));
  }
  return tables;
}

CellToPixelsTable repeat_cells(const CellToPixelsTable& table, std::uint32_t times) {
  const std::uint64_t cells = std::uint64_t{table.cell_count()} * times;
  if (cells > std::numeric_limits<std::uint32_t>::max()) {
    throw std::invalid_argument("LUT-1 of " + std::to_string(table.cell_count()) +
                                " cells repeated " + std::to_string(times) +
                                " times has more than 2^32 - 1 cells");
  }
  const std::span<const std::uint64_t> offsets = table.offsets();
  const std::span<const FeatureRect> rects = table.rects();
  std::vector<std::uint64_t> repeated_offsets;
  repeated_offsets.reserve(static_cast<std::size_t>(cells) + 1);
  repeated_offsets.push_back(0);
  std::vector<FeatureRect> repeated_rects;
  repeated_rects.reserve(rects.size() * times);
  for (std::uint32_t copy = 0; copy < times; ++copy) {
    const std::uint64_t base = repeated_rects.size();
    for (std::size_t cell = 1; cell < offsets.size(); ++cell) {
      repeated_offsets.push_back(base + offsets[cell]);
    }
    repeated_rects.insert(repeated_rects.end(), rects.begin(), rects.end());
  }
  return {table.columns(), table.rows(), std::move(repeated_offsets), std::move(repeated_rects)};
}

}  // namespace safecell
