#include "safecell/validation/negative_controls.hpp"

#include <array>
#include <vector>

#include "safecell/cellsets/leb128.hpp"

namespace safecell {
namespace {

struct Strip {
  std::size_t first_line = 0;
  std::vector<LineRun> runs;
};

// The strips of one entry, decoded (the table checked them when it was made).
std::vector<Strip> strips_of(const PixelToCellsTable& table, std::size_t pixel) {
  const std::uint8_t* byte = table.strip_bytes().data() + table.offsets()[pixel];
  const std::uint8_t* const end = table.strip_bytes().data() + table.offsets()[pixel + 1];
  std::vector<Strip> strips;
  std::size_t line = 0;
  while (byte != end) {
    line += read_leb128(byte);
    Strip strip{line, std::vector<LineRun>(*byte++)};
    for (LineRun& run : strip.runs) {
      run.first = static_cast<std::uint32_t>(read_leb128(byte));
      run.length = static_cast<std::uint32_t>(read_leb128(byte));
    }
    strips.push_back(std::move(strip));
  }
  return strips;
}

// Whether a strip starts in the dropped band: lines [1/2, 3/4) of its level's lines.
bool in_dropped_band(const LineLevels& levels, std::size_t first_line) {
  const std::uint32_t level = levels.level_of(first_line);
  const auto at = static_cast<double>(first_line - levels.first_line[level]) /
                  static_cast<double>(levels.lines_of(level));
  return at >= 0.5 && at < 0.75;
}

PixelToCellsTable drop_band_strips(const PixelToCellsTable& table, const CspaceGrid& grid) {
  std::vector<std::uint64_t> offsets{0};
  std::vector<std::uint8_t> bytes;
  for (std::size_t pixel = 0; pixel < table.pixel_count(); ++pixel) {
    std::size_t previous = 0;
    for (const Strip& strip : strips_of(table, pixel)) {
      if (in_dropped_band(table.levels(), strip.first_line)) continue;
      PixelToCellsTable::append_strip(bytes, previous, strip.first_line, strip.runs);
      previous = strip.first_line;
    }
    offsets.push_back(bytes.size());
  }
  return PixelToCellsTable(grid, table.columns(), table.rows(), std::move(offsets),
                           std::move(bytes));
}

constexpr std::array<NegativeControl, 4> kControls = {
    NegativeControl::kNone, NegativeControl::kEmptyMasks, NegativeControl::kDroppedStrip,
    NegativeControl::kEnvelopeRemoval};

}  // namespace

const char* to_string(NegativeControl control) {
  switch (control) {
    case NegativeControl::kNone:
      return "none";
    case NegativeControl::kEmptyMasks:
      return "empty-masks";
    case NegativeControl::kDroppedStrip:
      return "dropped-strip";
    case NegativeControl::kEnvelopeRemoval:
      return "envelope-removal";
  }
  return "unknown";
}

std::optional<NegativeControl> negative_control_named(const std::string& name) {
  for (const NegativeControl control : kControls) {
    if (name == to_string(control)) return control;
  }
  return std::nullopt;
}

LutSet with_strip_dropped(const LutSet& luts, const CspaceGrid& grid) {
  LutSet damaged = luts;
  for (CameraLuts& camera : damaged.cameras) {
    for (PartLuts& part : camera.parts) {
      part.pixel_to_cells = drop_band_strips(part.pixel_to_cells, grid);
      part.pixel_blocks.clear();
      for (auto& differences : part.differences) differences.clear();
    }
  }
  return damaged;
}

}  // namespace safecell
