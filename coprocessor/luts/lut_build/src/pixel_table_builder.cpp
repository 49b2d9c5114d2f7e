#include "safecell/lut_build/pixel_table_builder.hpp"

#include <algorithm>
#include <span>
#include <stdexcept>
#include <string>

#include "safecell/tables/strip_cover.hpp"

namespace safecell {
namespace {

// Cells per chunk of the gather: a multiple of 64, so that chunks own whole words.
constexpr std::size_t kGatherCells = std::size_t{64} * 1024;

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
void append_band(std::span<const CellSet> sets, std::size_t columns, bool first_band,
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
  // The bitsets of a band at every level, allocated once: on a fine grid a band is a gigabyte,
  // and allocating it anew per band (and per level) cost more than filling it.
  std::vector<std::vector<CellSet>> band_sets(levels.size());
  for (std::size_t l = 0; l < levels.size(); ++l) {
    const std::size_t level_rows = (static_cast<std::size_t>(band_rows) >> l) + 1;
    band_sets[l].assign(
        std::min<std::size_t>(level_rows, static_cast<std::size_t>(levels[l].rows)) *
            static_cast<std::size_t>(levels[l].columns),
        CellSet(grid.cell_count()));
  }
  for (int band = 0; band < rows; band += band_rows) {
    const int band_end = std::min(rows, band + band_rows);
    std::span<CellSet> sets(band_sets[0].data(), static_cast<std::size_t>(band_end - band) *
                                                     static_cast<std::size_t>(columns));
    parallel_chunks(sets.size(), 1, build.threads,
                    [&](std::size_t, std::size_t begin, std::size_t) { sets[begin].clear(); });
    // Gather: one pass over the cells per band, in chunks of whole 64-cell words, so that no two
    // threads write the same word of a bitset (a pass per feature row cost a pass over every
    // cell's rectangles per row: minutes on a fine grid).
    parallel_chunks(grid.cell_count(), kGatherCells, build.threads,
                    [&](std::size_t, std::size_t begin, std::size_t end) {
                      for (auto cell = static_cast<CellIndex>(begin); cell < end; ++cell) {
                        for (const auto& rect : cell_table.rects_of(cell)) {
                          const int first_row = std::max<int>(rect.row0, band);
                          const int end_row = std::min<int>(rect.row1 + 1, band_end);
                          for (int row = first_row; row < end_row; ++row) {
                            CellSet* row_cells =
                                sets.data() + static_cast<std::size_t>(row - band) *
                                                  static_cast<std::size_t>(columns);
                            for (int column = rect.col0; column <= rect.col1; ++column) {
                              row_cells[column].set(cell);
                            }
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
      const std::span<CellSet> coarse(
          band_sets[l].data(),
          static_cast<std::size_t>(coarse_columns) * static_cast<std::size_t>(coarse_rows));
      const auto fine_width = static_cast<std::size_t>(set_columns);
      const auto fine_rows = static_cast<std::size_t>(set_rows);
      const auto coarse_width = static_cast<std::size_t>(coarse_columns);
      parallel_chunks(coarse.size(), 1, build.threads,
                      [&](std::size_t, std::size_t begin, std::size_t) {
                        CellSet& block = coarse[begin];
                        block.clear();
                        const std::size_t x = begin % coarse_width * 2;
                        const std::size_t y = begin / coarse_width * 2;
                        for (std::size_t fy = y; fy < std::min(y + 2, fine_rows); ++fy) {
                          for (std::size_t fx = x; fx < std::min(x + 2, fine_width); ++fx) {
                            block |= sets[fy * fine_width + fx];
                          }
                        }
                      });
      sets = coarse;
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
