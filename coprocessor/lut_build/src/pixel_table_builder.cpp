#include "safecell/lut_build/pixel_table_builder.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>

#include "safecell/tables/strip_cover.hpp"

namespace safecell {
namespace {

// Entries as they are built, in row-major block order.
struct EntriesBuild {
  std::vector<std::uint64_t> offsets{0};
  std::vector<std::uint8_t> strip_bytes;
};

// One level of the pyramid as it is built: the strips of its blocks and of their differences to
// their neighbours.
struct LevelBuild {
  int block = 1;  // pixels per block side
  int columns = 0;
  int rows = 0;
  EntriesBuild entries;
  std::array<EntriesBuild, kNeighbourCount> differences;
};

void append_entries(const std::vector<std::vector<std::uint8_t>>& entries, EntriesBuild& build) {
  for (const auto& entry : entries) {
    build.offsets.push_back(build.offsets.back() + entry.size());
    build.strip_bytes.insert(build.strip_bytes.end(), entry.begin(), entry.end());
  }
}

// Cuts the sets of one band's blocks (rows of `columns` blocks) into strips (in parallel) and
// appends them to the level. first_band: the band holds the image's top row.
void append_band(std::vector<CellSet>& sets, std::size_t columns, bool first_band,
                 const BoxAxes& axes, unsigned threads, LevelBuild& level) {
  std::vector<std::vector<std::uint8_t>> strips(sets.size());
  std::array<std::vector<std::vector<std::uint8_t>>, kNeighbourCount> differences;
  for (auto& entries : differences) entries.resize(sets.size());
  parallel_chunks(sets.size(), 16, threads, [&](std::size_t, std::size_t begin, std::size_t end) {
    for (std::size_t i = begin; i < end; ++i) {
      append_strips(sets[i], axes, strips[i]);
      if (i % columns != 0) {
        append_strips(sets[i], axes, differences[kLeftNeighbour][i], &sets[i - 1]);
      }
      if (i >= columns) {
        append_strips(sets[i], axes, differences[kUpperNeighbour][i], &sets[i - columns]);
      } else if (!first_band) {
        differences[kUpperNeighbour][i] = strips[i];
      }
    }
  });
  append_entries(strips, level.entries);
  for (std::size_t n = 0; n < kNeighbourCount; ++n) {
    append_entries(differences[n], level.differences[n]);
  }
}

}  // namespace

PartLuts build_pixel_to_cells_tables(const CellToPixelsTable& cell_table, const CspaceGrid& grid,
                                     const PixelTableBuild& build,
                                     const ProgressCallback& progress) {
  if (cell_table.cell_count() != grid.cell_count()) {
    throw std::invalid_argument("LUT-1 has " + std::to_string(cell_table.cell_count()) +
                                " cells, the grid " + std::to_string(grid.cell_count()));
  }
  if (build.block_levels < 0 || build.block_levels > kMaxBlockLevels) {
    throw std::invalid_argument("LUT-2 block levels must be 0.." + std::to_string(kMaxBlockLevels) +
                                ", got " + std::to_string(build.block_levels));
  }
  const BoxAxes axes = BoxAxes::of(grid);
  const int columns = cell_table.columns();
  const int rows = cell_table.rows();
  const int top_block = 1 << build.block_levels;
  // Bands of whole top-level blocks, as many rows as the memory budget allows.
  const std::size_t bytes_per_row = static_cast<std::size_t>(columns) *
                                    ((static_cast<std::size_t>(grid.cell_count()) + 63) / 64) * 8;
  const auto affordable = static_cast<int>(std::min<std::size_t>(
      build.memory_budget_bytes / std::max<std::size_t>(bytes_per_row, 1), 1U << 20));
  const int band_rows = std::max(top_block, affordable / top_block * top_block);

  std::vector<LevelBuild> levels(static_cast<std::size_t>(build.block_levels) + 1);
  for (std::size_t l = 0; l < levels.size(); ++l) {
    levels[l].block = 1 << l;
    levels[l].columns = (columns + levels[l].block - 1) / levels[l].block;
    levels[l].rows = (rows + levels[l].block - 1) / levels[l].block;
  }
  for (int band = 0; band < rows; band += band_rows) {
    const int band_end = std::min(rows, band + band_rows);
    std::vector<CellSet> sets(
        static_cast<std::size_t>(band_end - band) * static_cast<std::size_t>(columns),
        CellSet(grid.cell_count()));
    // Gather: one feature row per chunk, so that no two threads write the same bitset.
    parallel_chunks(static_cast<std::size_t>(band_end - band), 1, build.threads,
                    [&](std::size_t, std::size_t begin, std::size_t) {
                      const int row = band + static_cast<int>(begin);
                      CellSet* row_cells = sets.data() + begin * static_cast<std::size_t>(columns);
                      for (CellIndex cell = 0; cell < grid.cell_count(); ++cell) {
                        for (const auto& rect : cell_table.rects_of(cell)) {
                          if (rect.row0 > row || rect.row1 < row) continue;
                          for (int column = rect.col0; column <= rect.col1; ++column) {
                            row_cells[column].set(cell);
                          }
                        }
                      }
                    });
    append_band(sets, static_cast<std::size_t>(columns), band == 0, axes, build.threads, levels[0]);
    // Each coarser level: the union of the (up to) four blocks below it.
    int set_columns = columns;
    int set_rows = band_end - band;
    for (std::size_t l = 1; l < levels.size(); ++l) {
      const int coarse_columns = (set_columns + 1) / 2;
      const int coarse_rows = (set_rows + 1) / 2;
      std::vector<CellSet> coarse(
          static_cast<std::size_t>(coarse_columns) * static_cast<std::size_t>(coarse_rows),
          CellSet(grid.cell_count()));
      const auto fine_width = static_cast<std::size_t>(set_columns);
      const auto coarse_width = static_cast<std::size_t>(coarse_columns);
      for (std::size_t y = 0; y < static_cast<std::size_t>(set_rows); ++y) {
        for (std::size_t x = 0; x < fine_width; ++x) {
          coarse[y / 2 * coarse_width + x / 2] |= sets[y * fine_width + x];
        }
      }
      sets = std::move(coarse);
      set_columns = coarse_columns;
      set_rows = coarse_rows;
      append_band(sets, static_cast<std::size_t>(set_columns), band == 0, axes, build.threads,
                  levels[l]);
    }
    if (progress) progress(static_cast<double>(band_end) / rows);
  }
  PartLuts tables;
  tables.covered_pairs = cell_table.covered_pairs();
  for (std::size_t l = 0; l < levels.size(); ++l) {
    const auto table_of = [&grid, &level = levels[l]](EntriesBuild& entries) {
      return PixelToCellsTable(grid, level.columns, level.rows, std::move(entries.offsets),
                               std::move(entries.strip_bytes));
    };
    PixelToCellsTable table = table_of(levels[l].entries);
    if (l == 0) {
      tables.pixel_to_cells = std::move(table);
    } else {
      tables.pixel_blocks.push_back(std::move(table));
    }
    for (std::size_t n = 0; n < kNeighbourCount; ++n) {
      tables.differences[n].push_back(table_of(levels[l].differences[n]));
    }
  }
  return tables;
}

}  // namespace safecell
