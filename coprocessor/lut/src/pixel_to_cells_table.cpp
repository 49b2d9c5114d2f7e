#include "safecell/lut/pixel_to_cells_table.hpp"

#include <stdexcept>
#include <string>

namespace safecell {
namespace {

struct OwnedArrays {
  std::vector<std::uint64_t> offsets;
  std::vector<std::uint8_t> box_bytes;
};

}  // namespace

PixelToCellsTable::PixelToCellsTable(const CspaceGrid& grid, int columns, int rows,
                                     std::vector<std::uint64_t> offsets,
                                     std::vector<std::uint8_t> box_bytes)
    : columns_(columns), rows_(rows), cell_count_(grid.cell_count()), axes_(BoxAxes::of(grid)) {
  auto owned = std::make_shared<OwnedArrays>(OwnedArrays{std::move(offsets), std::move(box_bytes)});
  offsets_ = owned->offsets;
  box_bytes_ = owned->box_bytes;
  storage_ = std::move(owned);
  check();
}

PixelToCellsTable::PixelToCellsTable(const CspaceGrid& grid, int columns, int rows,
                                     std::span<const std::uint64_t> offsets,
                                     std::span<const std::uint8_t> box_bytes,
                                     std::shared_ptr<const void> storage)
    : columns_(columns),
      rows_(rows),
      cell_count_(grid.cell_count()),
      axes_(BoxAxes::of(grid)),
      offsets_(offsets),
      box_bytes_(box_bytes),
      storage_(std::move(storage)) {
  check();
}

void PixelToCellsTable::append_box(std::vector<std::uint8_t>& bytes, CellIndex previous_start,
                                   CellIndex start, const std::uint32_t* extents,
                                   std::uint32_t axes) {
  CellIndex delta = start - previous_start;
  while (delta >= 0x80U) {
    bytes.push_back(static_cast<std::uint8_t>((delta & 0x7FU) | 0x80U));
    delta >>= 7;
  }
  bytes.push_back(static_cast<std::uint8_t>(delta));
  for (std::uint32_t axis = 0; axis < axes; ++axis) {
    bytes.push_back(static_cast<std::uint8_t>(extents[axis]));
  }
}

void PixelToCellsTable::check() {
  if (columns_ < 1 || rows_ < 1) throw std::invalid_argument("LUT-2: empty pixel grid");
  const std::size_t pixels = static_cast<std::size_t>(columns_) * static_cast<std::size_t>(rows_);
  if (offsets_.size() != pixels + 1 || offsets_.front() != 0 ||
      offsets_.back() != box_bytes_.size()) {
    throw std::invalid_argument("LUT-2: " + std::to_string(offsets_.size()) + " offsets for " +
                                std::to_string(pixels) + " pixels do not span the " +
                                std::to_string(box_bytes_.size()) + " box bytes");
  }
  // Every box is decoded once: it must end inside its pixel's bytes and stay inside the grid
  // along each axis, so that decoding in fusion can never leave the cell set.
  total_boxes_ = 0;
  for (std::size_t pixel = 0; pixel < pixels; ++pixel) {
    if (offsets_[pixel + 1] < offsets_[pixel]) {
      throw std::invalid_argument("LUT-2: offsets fall at pixel " + std::to_string(pixel));
    }
    std::uint64_t at = offsets_[pixel];
    const std::uint64_t end = offsets_[pixel + 1];
    std::uint64_t start = 0;
    while (at < end) {
      std::uint64_t delta = 0;
      int shift = 0;
      while (true) {
        if (at >= end || shift > 28) {
          throw std::invalid_argument("LUT-2: a box of pixel " + std::to_string(pixel) +
                                      " is cut off or its cell number is too long");
        }
        const std::uint8_t byte = box_bytes_[at++];
        delta |= std::uint64_t{byte & 0x7FU} << shift;
        shift += 7;
        if ((byte & 0x80U) == 0) break;
      }
      start += delta;
      if (start >= cell_count_ || end - at < axes_.count) {
        throw std::invalid_argument("LUT-2: a box of pixel " + std::to_string(pixel) +
                                    " starts outside the grid or is cut off");
      }
      for (std::uint32_t axis = 0; axis < axes_.count; ++axis) {
        const std::uint64_t coord = start / axes_.stride[axis] % axes_.cells[axis];
        const std::uint32_t extent = box_bytes_[at + axis];
        if (extent == 0 || coord + extent > axes_.cells[axis]) {
          throw std::invalid_argument("LUT-2: a box of pixel " + std::to_string(pixel) +
                                      " leaves the grid along joint " +
                                      std::to_string(axes_.joint[axis] + 1));
        }
      }
      at += axes_.count;
      ++total_boxes_;
    }
  }
}

void PixelToCellsTable::add_cells(std::size_t pixel, CellSet& cells) const {
  for_each_box(pixel, [&](CellIndex start, const std::uint8_t* extents) {
    for_each_box_row(axes_, start, extents, [&cells](CellIndex first, std::uint32_t run) {
      cells.set_range(first, first + run);
    });
  });
}

std::size_t PixelToCellsTable::add_cells(std::size_t pixel, CellLines& cells) const {
  std::size_t lines = 0;
  for_each_box(pixel, [&](CellIndex start, const std::uint8_t* extents) {
    lines += cells.add_box(start, extents);
  });
  return lines;
}

}  // namespace safecell
