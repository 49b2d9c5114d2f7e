#include "safecell/tables/strip_cover.hpp"

#include <algorithm>

#include "safecell/cellsets/cell_slices.hpp"
#include "safecell/cellsets/line_levels.hpp"
#include "safecell/tables/pixel_to_cells_table.hpp"

namespace safecell {
namespace {

constexpr std::size_t kMaxStripLines = 255;  // one count byte

struct Strip {
  std::size_t first_line = 0;
  std::vector<LineRun> runs;  // one per line from first_line on
};

// Collects runs line by line (ascending) into strips: the j-th run of a line continues the strip
// of the j-th runs when that strip ended on the line before.
class StripCollector {
 public:
  void add(std::size_t line, LineRun run) {
    if (line != line_) {
      line_ = line;
      run_in_line_ = 0;
    }
    if (run_in_line_ == open_.size()) open_.emplace_back();
    Strip& strip = open_[run_in_line_++];
    if (strip.runs.empty() || strip.first_line + strip.runs.size() != line ||
        strip.runs.size() == kMaxStripLines) {
      if (!strip.runs.empty()) done_.push_back(std::move(strip));
      strip = Strip{line, {}};
    }
    strip.runs.push_back(run);
  }

  // All strips, in ascending order of their first line.
  std::vector<Strip> finish() {
    for (Strip& strip : open_) {
      if (!strip.runs.empty()) done_.push_back(std::move(strip));
    }
    open_.clear();
    std::stable_sort(done_.begin(), done_.end(),
                     [](const Strip& a, const Strip& b) { return a.first_line < b.first_line; });
    return std::move(done_);
  }

 private:
  std::vector<Strip> open_;
  std::vector<Strip> done_;
  std::size_t line_ = ~std::size_t{0};
  std::size_t run_in_line_ = 0;
};

}  // namespace

namespace {

// sets[d] for d = 1..axes.count: the cells over the first d axes whose cells hold along all
// remaining axes; sets[axes.count] is `cells`.
std::vector<CellSet> level_sets_of(const CellSet& cells, const BoxAxes& axes) {
  std::vector<CellSet> sets(axes.count + 1);
  sets[axes.count] = cells;
  for (std::uint32_t d = axes.count - 1; d >= 1; --d) {
    sets[d] = cells_in_every_slice(sets[d + 1], axes.stride[d], axes.cells[d]);
  }
  return sets;
}

}  // namespace

std::size_t append_strips(const CellSet& cells, const BoxAxes& axes,
                          std::vector<std::uint8_t>& strip_bytes, const CellSet* known) {
  const LineLevels levels = LineLevels::of(axes, cells.cell_count());
  const std::vector<CellSet> level_sets = level_sets_of(cells, axes);
  const std::vector<CellSet> known_sets =
      known != nullptr ? level_sets_of(*known, axes) : std::vector<CellSet>{};
  StripCollector collector;
  for (std::uint32_t d = 1; d <= axes.count; ++d) {
    const CellSet& set = level_sets[d];
    CellSet covered =
        d == 1 ? CellSet(set.cell_count()) : repeat_slice(level_sets[d - 1], axes.cells[d - 1]);
    if (known != nullptr) covered |= known_sets[d];
    for (CellIndex first = set.next_set(0); first < set.cell_count();) {
      const CellIndex line = first / levels.line_cells;
      const CellIndex line_end = (line + 1) * levels.line_cells;
      const CellIndex end = set.next_clear(first, line_end);
      if (!covered.all_in_range(first, end)) {
        collector.add(levels.first_line[d] + line,
                      LineRun{first - line * levels.line_cells, end - first});
      }
      first = set.next_set(end);
    }
  }
  const std::vector<Strip> strips = collector.finish();
  std::size_t previous_first_line = 0;
  for (const Strip& strip : strips) {
    PixelToCellsTable::append_strip(strip_bytes, previous_first_line, strip.first_line, strip.runs);
    previous_first_line = strip.first_line;
  }
  return strips.size();
}

}  // namespace safecell
