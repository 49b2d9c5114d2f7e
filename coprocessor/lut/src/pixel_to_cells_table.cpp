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

void PixelToCellsTable::check() const {
  if (columns_ < 1 || rows_ < 1) throw std::invalid_argument("LUT-2: empty feature grid");
  const std::size_t pixels = static_cast<std::size_t>(columns_) * static_cast<std::size_t>(rows_);
  if (offsets_.size() != pixels + 1 || offsets_.front() != 0) {
    throw std::invalid_argument("LUT-2: " + std::to_string(offsets_.size()) + " offsets for " +
                                std::to_string(pixels) + " pixels");
  }
  const std::uint32_t bytes_per_box = axes_.bytes_per_box();
  if (offsets_.back() * bytes_per_box != box_bytes_.size()) {
    throw std::invalid_argument("LUT-2: the offsets do not span the boxes");
  }
  for (std::size_t i = 1; i < offsets_.size(); ++i) {
    if (offsets_[i] < offsets_[i - 1]) {
      throw std::invalid_argument("LUT-2: offsets fall at pixel " + std::to_string(i - 1));
    }
  }
  // Every box must stay inside the grid along each axis, so that decoding cannot leave the set.
  for (std::size_t box = 0; box < offsets_.back(); ++box) {
    const std::uint8_t* bytes = box_bytes_.data() + box * bytes_per_box;
    const CellIndex start = box_start(bytes);
    if (start >= cell_count_) throw std::invalid_argument("LUT-2: a box starts outside the grid");
    for (std::uint32_t axis = axes_.count; axis-- > 0;) {
      const std::uint32_t coord = start / axes_.stride[axis] % axes_.cells[axis];
      const std::uint32_t extent = bytes[4 + axis];
      if (extent == 0 || coord + extent > axes_.cells[axis]) {
        throw std::invalid_argument("LUT-2: box " + std::to_string(box) +
                                    " leaves the grid along joint " +
                                    std::to_string(axes_.joint[axis] + 1));
      }
    }
  }
}

void PixelToCellsTable::add_cells(std::size_t pixel, CellSet& cells) const {
  const std::uint32_t bytes_per_box = axes_.bytes_per_box();
  const std::uint8_t* box = box_bytes_.data() + offsets_[pixel] * bytes_per_box;
  const std::uint8_t* end = box_bytes_.data() + offsets_[pixel + 1] * bytes_per_box;
  for (; box != end; box += bytes_per_box) {
    for_each_box_row(axes_, box_start(box), box + 4, [&cells](CellIndex first, std::uint32_t run) {
      cells.set_range(first, first + run);
    });
  }
}

}  // namespace safecell
