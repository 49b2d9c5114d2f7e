#include "safecell/lut_build/pixel_table_check.hpp"

#include <algorithm>
#include <mutex>
#include <stdexcept>
#include <tuple>
#include <utility>

#include "safecell/cellsets/line_levels.hpp"

namespace safecell {
namespace {

// The sampled cells by line: for each level of the line layout, the global line number each
// sampled cell lies on there and its place along joint 0, sorted by line.
class SampleLines {
 public:
  SampleLines(const std::vector<CellIndex>& sample, const LineLevels& levels) {
    for (std::size_t s = 0; s < sample.size(); ++s) {
      for (std::uint32_t d = 1; d <= levels.count; ++d) {
        const CellIndex in_level = sample[s] % levels.level_cells[d];
        keys_.push_back(Key{levels.first_line[d] + in_level / levels.line_cells,
                            in_level % levels.line_cells, s});
      }
    }
    std::sort(keys_.begin(), keys_.end(),
              [](const Key& a, const Key& b) { return a.line < b.line; });
    first_key_.assign(levels.total_lines() + 1, 0);
    std::size_t key = 0;
    for (std::size_t line = 0; line <= levels.total_lines(); ++line) {
      while (key < keys_.size() && keys_[key].line < line) ++key;
      first_key_[line] = static_cast<std::uint32_t>(key);
    }
  }

  // Sets named[s] for every sampled cell s that `run` of global line `line` holds.
  void mark(std::size_t line, LineRun run, std::vector<char>& named) const {
    for (std::uint32_t k = first_key_[line]; k < first_key_[line + 1]; ++k) {
      const Key& key = keys_[k];
      if (key.along >= run.first && key.along - run.first < run.length) named[key.sample] = 1;
    }
  }

 private:
  struct Key {
    std::size_t line = 0;
    CellIndex along = 0;  // the cell's place along joint 0
    std::size_t sample = 0;
  };
  std::vector<Key> keys_;
  std::vector<std::uint32_t> first_key_;  // per line, its first key; one more at the end
};

// The sampled cells one entry names.
void decode(const PixelToCellsTable& table, std::size_t entry, const SampleLines& lines,
            std::vector<char>& named) {
  std::fill(named.begin(), named.end(), 0);
  table.for_each_line_run(entry,
                          [&](std::size_t line, LineRun run) { lines.mark(line, run, named); });
}

// What the silhouettes say: expected[s * tables + part * cameras + camera] is the silhouette of
// sampled cell s.
struct Expected {
  std::size_t cameras = 0;
  std::size_t tables = 0;
  std::vector<FeatureMask> masks;

  // Whether a pixel of the block (column, row) of 2^level pixels a side holds sampled cell s.
  [[nodiscard]] bool holds(std::size_t s, std::size_t part, std::size_t camera, int level,
                           int column, int row) const {
    const FeatureMask& mask = masks[s * tables + part * cameras + camera];
    const int size = 1 << level;
    for (int y = row * size; y < std::min(mask.rows(), (row + 1) * size); ++y) {
      for (int x = column * size; x < std::min(mask.columns(), (column + 1) * size); ++x) {
        if (mask.test(x, y)) return true;
      }
    }
    return false;
  }
};

Expected expected_silhouettes(const ModelSilhouettes& silhouettes,
                              const std::vector<CellIndex>& sample, unsigned threads) {
  Expected expected;
  expected.cameras = silhouettes.camera_count();
  expected.tables = silhouettes.parts().size() * expected.cameras;
  expected.masks.assign(sample.size() * expected.tables, FeatureMask(silhouettes.feature_grid()));
  parallel_chunks(sample.size(), 16, threads, [&](std::size_t, std::size_t begin, std::size_t end) {
    for (std::size_t s = begin; s < end; ++s) {
      for (std::size_t part = 0; part < silhouettes.parts().size(); ++part) {
        silhouettes.add_part_silhouettes(
            sample[s], part, expected.masks.data() + s * expected.tables + part * expected.cameras);
      }
    }
  });
  return expected;
}

void check_set_fits(const LutSet& luts, const ModelSilhouettes& silhouettes,
                    const std::vector<CellIndex>& sample) {
  if (luts.source != LutSource::kModel) {
    throw std::invalid_argument("the check compares model-mode tables with the model");
  }
  if (luts.cameras.size() != silhouettes.camera_count() ||
      luts.parts.size() != silhouettes.parts().size() ||
      luts.columns != silhouettes.feature_grid().columns() ||
      luts.rows != silhouettes.feature_grid().rows()) {
    throw std::invalid_argument("the tables are not of the silhouettes' cameras, parts and grid");
  }
  for (const CameraLuts& camera : luts.cameras) {
    if (camera.parts.size() != luts.parts.size()) {
      throw std::invalid_argument("camera " + camera.camera + " has tables of " +
                                  std::to_string(camera.parts.size()) + " parts, not " +
                                  std::to_string(luts.parts.size()));
    }
  }
  const std::uint32_t cells = luts.cameras.front().parts.front().pixel_to_cells.cell_count();
  for (const CellIndex cell : sample) {
    if (cell >= cells) {
      throw std::invalid_argument("sampled cell " + std::to_string(cell) + " outside the " +
                                  std::to_string(cells) + " cells of the tables");
    }
  }
}

// Table order: camera, part, level, block, then the entry's kind and the cell (a cell's place in
// the sample while the check runs, its number in the result).
bool in_table_order(const PixelTableMismatch& a, const PixelTableMismatch& b) {
  return std::tie(a.camera, a.part, a.level, a.row, a.column, a.entry, a.cell) <
         std::tie(b.camera, b.part, b.level, b.row, b.column, b.entry, b.cell);
}

// Collects the outcome of many chunks (called from several threads, in any order). Each chunk
// brings the first mismatches of its run of entries; keeping the first of all of them in table
// order gives the table's first mismatches, whichever chunk finished first.
class Tally {
 public:
  void add(PixelTableCheck& part) {
    const std::lock_guard lock(mutex_);
    total_.entries += part.entries;
    total_.pairs += part.pairs;
    total_.mismatches += part.mismatches;
    auto& first = total_.first_mismatches;
    first.insert(first.end(), part.first_mismatches.begin(), part.first_mismatches.end());
    std::sort(first.begin(), first.end(), in_table_order);
    if (first.size() > PixelTableCheck::kMaxReported) first.resize(PixelTableCheck::kMaxReported);
  }
  PixelTableCheck take() { return std::move(total_); }

 private:
  std::mutex mutex_;
  PixelTableCheck total_;
};

// One table of the check: a camera's part at one pyramid level.
struct LevelTables {
  std::size_t camera = 0;
  std::size_t part = 0;
  int level = 0;
  const PixelToCellsTable* cells = nullptr;
  const PixelToCellsTable* differences[kNeighbourCount]{};
};

void check_entry(const LevelTables& tables, const Expected& expected, const SampleLines& lines,
                 std::size_t entry, std::vector<char>& named, std::vector<char>& in_difference,
                 PixelTableCheck& out) {
  const int columns = tables.cells->columns();
  const int column = static_cast<int>(entry % static_cast<std::size_t>(columns));
  const int row = static_cast<int>(entry / static_cast<std::size_t>(columns));
  const auto report = [&](PixelTableEntry kind, std::size_t s, bool was_named) {
    ++out.mismatches;
    if (out.first_mismatches.size() < PixelTableCheck::kMaxReported) {
      out.first_mismatches.push_back(PixelTableMismatch{tables.camera, tables.part, tables.level,
                                                        kind, column, row,
                                                        static_cast<CellIndex>(s), was_named});
    }
  };
  const std::size_t cells = named.size();
  std::vector<char> holds(cells);
  for (std::size_t s = 0; s < cells; ++s) {
    holds[s] = expected.holds(s, tables.part, tables.camera, tables.level, column, row) ? 1 : 0;
  }
  decode(*tables.cells, entry, lines, named);
  ++out.entries;
  for (std::size_t s = 0; s < cells; ++s) {
    ++out.pairs;
    if (named[s] != holds[s]) report(PixelTableEntry::kCells, s, named[s] != 0);
  }
  for (std::size_t n = 0; n < kNeighbourCount; ++n) {
    if (tables.differences[n] == nullptr) continue;
    if (n == kLeftNeighbour ? column == 0 : row == 0) continue;  // no neighbour: never used
    const int neighbour_column = n == kLeftNeighbour ? column - 1 : column;
    const int neighbour_row = n == kLeftNeighbour ? row : row - 1;
    decode(*tables.differences[n], entry, lines, in_difference);
    ++out.entries;
    const auto kind =
        n == kLeftNeighbour ? PixelTableEntry::kLeftDifference : PixelTableEntry::kUpperDifference;
    for (std::size_t s = 0; s < cells; ++s) {
      ++out.pairs;
      const bool neighbour_holds = expected.holds(s, tables.part, tables.camera, tables.level,
                                                  neighbour_column, neighbour_row);
      // Only the entry's own cells, and with the neighbour's all of them.
      if (in_difference[s] != 0 && holds[s] == 0) report(kind, s, true);
      if (holds[s] != 0 && in_difference[s] == 0 && !neighbour_holds) report(kind, s, false);
    }
  }
}

}  // namespace

const char* to_string(PixelTableEntry entry) {
  switch (entry) {
    case PixelTableEntry::kCells:
      return "cells";
    case PixelTableEntry::kLeftDifference:
      return "difference to the left";
    case PixelTableEntry::kUpperDifference:
      return "difference to the block above";
  }
  return "?";
}

std::string describe(const PixelTableMismatch& mismatch, const LutSet& luts) {
  const std::string block = mismatch.level == 0
                                ? "feature cell"
                                : std::to_string(1 << mismatch.level) + "x" +
                                      std::to_string(1 << mismatch.level) + " block";
  return "camera " + luts.cameras.at(mismatch.camera).camera + ", part " +
         luts.parts.at(mismatch.part).name + ", " + block + " (" + std::to_string(mismatch.column) +
         ", " + std::to_string(mismatch.row) + "), " + to_string(mismatch.entry) +
         ": C-space cell " + std::to_string(mismatch.cell) +
         (mismatch.named ? " named by the table, not by the silhouettes"
                         : " in the silhouettes, not named by the table");
}

PixelTableCheck check_pixel_tables(const LutSet& luts, const ModelSilhouettes& silhouettes,
                                   std::vector<CellIndex> sample, unsigned threads,
                                   const ProgressCallback& progress) {
  check_set_fits(luts, silhouettes, sample);
  const Expected expected = expected_silhouettes(silhouettes, sample, threads);
  const PixelToCellsTable& any_table = luts.cameras.front().parts.front().pixel_to_cells;
  const SampleLines lines(sample, any_table.levels());

  std::vector<LevelTables> work;
  for (std::size_t camera = 0; camera < luts.cameras.size(); ++camera) {
    for (std::size_t part = 0; part < luts.parts.size(); ++part) {
      const PartLuts& tables = luts.cameras[camera].parts[part];
      for (std::size_t level = 0; level <= tables.pixel_blocks.size(); ++level) {
        LevelTables level_tables{
            camera, part, static_cast<int>(level), &tables.entries_of_level(level), {}};
        for (std::size_t n = 0; n < kNeighbourCount; ++n) {
          if (level < tables.differences[n].size()) {
            level_tables.differences[n] = &tables.differences[n][level];
          }
        }
        work.push_back(level_tables);
      }
    }
  }
  // Entries of every table, numbered one after the other, in chunks.
  std::vector<std::size_t> first_entry{0};
  for (const LevelTables& tables : work) {
    first_entry.push_back(first_entry.back() + tables.cells->pixel_count());
  }
  Tally tally;
  parallel_chunks(
      first_entry.back(), 64, threads,
      [&](std::size_t, std::size_t begin, std::size_t end) {
        PixelTableCheck chunk;
        std::vector<char> named(sample.size());
        std::vector<char> in_difference(sample.size());
        for (std::size_t index = begin; index < end; ++index) {
          const auto table = static_cast<std::size_t>(
              std::upper_bound(first_entry.begin(), first_entry.end(), index) -
              first_entry.begin() - 1);
          check_entry(work[table], expected, lines, index - first_entry[table], named,
                      in_difference, chunk);
        }
        tally.add(chunk);
      },
      progress);
  PixelTableCheck check = tally.take();
  check.cells = sample.size();
  // Report cells by number, not by their place in the sample; in table order.
  for (PixelTableMismatch& mismatch : check.first_mismatches) mismatch.cell = sample[mismatch.cell];
  std::sort(check.first_mismatches.begin(), check.first_mismatches.end(), in_table_order);
  return check;
}

}  // namespace safecell
