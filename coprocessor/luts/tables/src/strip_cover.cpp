#include "safecell/tables/strip_cover.hpp"

#include <algorithm>
#include <optional>

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

// The levels of a set: at(d) for d = 1..axes.count holds the cells over the first d axes whose
// cells hold along all remaining axes; the top level is the set itself, not a copy (on a fine
// grid it is megabytes, and a copy per pixel was most of a build's time).
class LevelSets {
 public:
  LevelSets(const CellSet& cells, const BoxAxes& axes) : top_(&cells), lower_(axes.count) {
    for (std::uint32_t d = axes.count - 1; d >= 1; --d) {
      lower_[d] = cells_in_every_slice(at(d + 1), axes.stride[d], axes.cells[d]);
    }
  }
  [[nodiscard]] const CellSet& at(std::uint32_t d) const {
    return d == lower_.size() ? *top_ : lower_[d];
  }

 private:
  const CellSet* top_;
  std::vector<CellSet> lower_;  // lower_[d] for d = 1..count-1; lower_[0] unused
};

// `count` (1..64) bits of `cells` from cell `first` on (precondition: first + count <=
// cells.cell_count()).
std::uint64_t bits_at(const CellSet& cells, CellIndex first, CellIndex count) {
  const std::vector<std::uint64_t>& words = cells.words();
  const std::size_t word = first / 64;
  const std::size_t shift = first % 64;
  std::uint64_t bits = words[word] >> shift;
  if (shift != 0 && shift + count > 64) bits |= words[word + 1] << (64 - shift);
  return count == 64 ? bits : bits & ((std::uint64_t{1} << count) - 1);
}

// Whether each of the cells first..first+length-1 of a line of level d is in the level below
// (repeated along axis d - 1: cell x of level d is cell x % lower.cell_count() there) or in
// `known` (of level d). The run lies in one line, and a line of level d is a line of the level
// below at x % lower.cell_count(), so the run is a run there too.
bool covered(const CellSet* lower, const CellSet* known, CellIndex first, CellIndex length) {
  const CellIndex lower_first = lower != nullptr ? first % lower->cell_count() : 0;
  for (CellIndex done = 0; done < length; done += 64) {
    const CellIndex count = std::min<CellIndex>(64, length - done);
    std::uint64_t bits = 0;
    if (lower != nullptr) bits |= bits_at(*lower, lower_first + done, count);
    if (known != nullptr) bits |= bits_at(*known, first + done, count);
    const std::uint64_t all = count == 64 ? ~std::uint64_t{0} : (std::uint64_t{1} << count) - 1;
    if (bits != all) return false;
  }
  return true;
}

}  // namespace

std::size_t append_strips(const CellSet& cells, const BoxAxes& axes,
                          std::vector<std::uint8_t>& strip_bytes, const CellSet* known) {
  const LineLevels levels = LineLevels::of(axes, cells.cell_count());
  const LevelSets level_sets(cells, axes);
  const std::optional<LevelSets> known_sets =
      known != nullptr ? std::optional<LevelSets>(std::in_place, *known, axes) : std::nullopt;
  StripCollector collector;
  for (std::uint32_t d = 1; d <= axes.count; ++d) {
    const CellSet& set = level_sets.at(d);
    const CellSet* lower = d == 1 ? nullptr : &level_sets.at(d - 1);
    const CellSet* known_here = known_sets ? &known_sets->at(d) : nullptr;
    for (CellIndex first = set.next_set(0); first < set.cell_count();) {
      const CellIndex line = first / levels.line_cells;
      const CellIndex line_end = (line + 1) * levels.line_cells;
      const CellIndex end = set.next_clear(first, line_end);
      if (!covered(lower, known_here, first, end - first)) {
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
