#include "safecell/tables/pixel_to_cells_table.hpp"

#include <stdexcept>
#include <string>

namespace safecell {
namespace {

struct OwnedArrays {
  std::vector<std::uint64_t> offsets;
  std::vector<std::uint8_t> strip_bytes;
};

// Longest LEB128 form of a line number or a run (both below 2^35).
constexpr int kMaxLeb128Bytes = 5;

}  // namespace

PixelToCellsTable::PixelToCellsTable(const CspaceGrid& grid, int columns, int rows,
                                     std::vector<std::uint64_t> offsets,
                                     std::vector<std::uint8_t> strip_bytes)
    : columns_(columns),
      rows_(rows),
      cell_count_(grid.cell_count()),
      axes_(BoxAxes::of(grid)),
      levels_(LineLevels::of(axes_, cell_count_)) {
  auto owned =
      std::make_shared<OwnedArrays>(OwnedArrays{std::move(offsets), std::move(strip_bytes)});
  offsets_ = owned->offsets;
  strip_bytes_ = owned->strip_bytes;
  storage_ = std::move(owned);
  check();
}

PixelToCellsTable::PixelToCellsTable(const CspaceGrid& grid, int columns, int rows,
                                     std::span<const std::uint64_t> offsets,
                                     std::span<const std::uint8_t> strip_bytes,
                                     std::shared_ptr<const void> storage)
    : columns_(columns),
      rows_(rows),
      cell_count_(grid.cell_count()),
      axes_(BoxAxes::of(grid)),
      levels_(LineLevels::of(axes_, cell_count_)),
      offsets_(offsets),
      strip_bytes_(strip_bytes),
      storage_(std::move(storage)) {
  check();
}

void PixelToCellsTable::append_strip(std::vector<std::uint8_t>& bytes,
                                     std::size_t previous_first_line, std::size_t first_line,
                                     std::span<const LineRun> runs) {
  if (first_line < previous_first_line || runs.empty() || runs.size() > 255) {
    throw std::invalid_argument("LUT-2 strip out of order or of " + std::to_string(runs.size()) +
                                " lines");
  }
  append_leb128(bytes, first_line - previous_first_line);
  bytes.push_back(static_cast<std::uint8_t>(runs.size()));
  for (const LineRun& run : runs) {
    append_leb128(bytes, run.first);
    append_leb128(bytes, run.length);
  }
}

void PixelToCellsTable::add_cells(std::size_t pixel, CellSet& cells) const {
  for_each_cell_run(pixel, [&cells](CellIndex first, std::uint32_t length) {
    cells.set_range(first, first + length);
  });
}

void PixelToCellsTable::check() {
  if (columns_ < 1 || rows_ < 1) throw std::invalid_argument("LUT-2: empty pixel grid");
  const std::size_t pixels = static_cast<std::size_t>(columns_) * static_cast<std::size_t>(rows_);
  if (offsets_.size() != pixels + 1 || offsets_.front() != 0 ||
      offsets_.back() != strip_bytes_.size()) {
    throw std::invalid_argument("LUT-2: " + std::to_string(offsets_.size()) + " offsets for " +
                                std::to_string(pixels) + " pixels do not span the " +
                                std::to_string(strip_bytes_.size()) + " strip bytes");
  }
  // Every strip is decoded once: it must end inside its pixel's bytes, its lines inside the
  // levels and its runs inside their lines, each number in its shortest form (fusion reads a
  // number below 128 as one byte), so that decoding in fusion can never leave the cell set.
  total_strips_ = 0;
  const std::size_t lines = levels_.total_lines();
  for (std::size_t pixel = 0; pixel < pixels; ++pixel) {
    if (offsets_[pixel + 1] < offsets_[pixel]) {
      throw std::invalid_argument("LUT-2: offsets fall at pixel " + std::to_string(pixel));
    }
    const auto fail = [pixel](const std::string& what) {
      throw std::invalid_argument("LUT-2: a strip of pixel " + std::to_string(pixel) + " " + what);
    };
    const std::uint8_t* at = strip_bytes_.data() + offsets_[pixel];
    const std::uint8_t* const end = strip_bytes_.data() + offsets_[pixel + 1];
    std::uint64_t line = 0;
    while (at < end) {
      std::uint64_t delta = 0;
      if (!read_leb128_checked(at, end, kMaxLeb128Bytes, delta)) {
        fail("is cut off or its line number is malformed");
      }
      line += delta;
      if (at >= end) fail("is cut off before its line count");
      const std::uint32_t count = *at++;
      if (count == 0 || line >= lines || count > lines - line) {
        fail("has " + std::to_string(count) + " lines from line " + std::to_string(line) +
             ", outside the " + std::to_string(lines) + " lines");
      }
      for (std::uint32_t k = 0; k < count; ++k) {
        std::uint64_t first = 0;
        std::uint64_t length = 0;
        if (!read_leb128_checked(at, end, kMaxLeb128Bytes, first) ||
            !read_leb128_checked(at, end, kMaxLeb128Bytes, length)) {
          fail("is cut off or a run of it is malformed");
        }
        if (length == 0 || first + length > levels_.line_cells) {
          fail("has a run of " + std::to_string(length) + " cells from cell " +
               std::to_string(first) + ", outside the line of " +
               std::to_string(levels_.line_cells));
        }
      }
      ++total_strips_;
    }
  }
}

}  // namespace safecell
