#include "safecell/lut/box_cover.hpp"

#include <algorithm>

#include "safecell/lut/cell_slices.hpp"
#include "safecell/lut/pixel_to_cells_table.hpp"

namespace safecell {
namespace {

constexpr std::uint32_t kMaxExtent = 255;  // one byte per extent

struct Box {
  CellIndex start = 0;
  std::uint32_t extents[kMaxJoints]{};
};

// Whether every row of the box (start, extents) lies in `cells`.
bool box_inside(const CellSet& cells, const BoxAxes& axes, CellIndex start,
                const std::uint32_t* extents) {
  bool inside = true;
  for_each_box_row(axes, start, extents, [&](CellIndex first, std::uint32_t run) {
    inside = inside && cells.all_in_range(first, first + run);
  });
  return inside;
}

// The first `count` axes of `axes`: the grid of one level.
BoxAxes leading_axes(const BoxAxes& axes, std::uint32_t count) {
  BoxAxes leading = axes;
  leading.count = count;
  return leading;
}

// Greedy boxes over `axes` for the cells of `cells` not in `covered` (see the header); every box
// gets `full_extents` along the axes after axes.count.
void cover(const CellSet& cells, CellSet covered, const BoxAxes& axes,
           const std::uint32_t* full_extents, std::vector<Box>& boxes) {
  CellSet uncovered = cells;
  for (std::size_t w = 0; w < uncovered.words().size(); ++w) {
    uncovered.words()[w] &= ~covered.words()[w];
  }
  for (CellIndex seed = uncovered.next_set(0); seed < uncovered.cell_count();
       seed = uncovered.next_set(seed)) {
    std::uint32_t coord[kMaxJoints]{};
    for (std::uint32_t axis = 0; axis < axes.count; ++axis) {
      coord[axis] = seed / axes.stride[axis] % axes.cells[axis];
    }
    Box box;
    std::copy(full_extents, full_extents + kMaxJoints, box.extents);
    box.start = seed;
    std::uint32_t* extents = box.extents;
    for (std::uint32_t axis = 0; axis < axes.count; ++axis) extents[axis] = 1;
    // Forwards first, so that a run longer than one box still advances past the seed.
    while (coord[0] + extents[0] < axes.cells[0] && extents[0] < kMaxExtent &&
           cells.test(box.start + extents[0])) {
      ++extents[0];
    }
    while (coord[0] > 0 && extents[0] < kMaxExtent && cells.test(box.start - 1)) {
      --box.start;
      --coord[0];
      ++extents[0];
    }
    for (std::uint32_t axis = 1; axis < axes.count; ++axis) {
      while (coord[axis] + extents[axis] < axes.cells[axis] && extents[axis] < kMaxExtent) {
        // The next layer along this axis: the box so far, moved by `extents[axis]` steps.
        std::uint32_t layer[kMaxJoints]{};
        std::copy(extents, extents + axes.count, layer);
        layer[axis] = 1;
        const CellIndex layer_start = box.start + extents[axis] * axes.stride[axis];
        if (!box_inside(cells, axes, layer_start, layer) ||
            box_inside(covered, axes, layer_start, layer)) {
          break;
        }
        ++extents[axis];
      }
    }
    for_each_box_row(axes, box.start, extents, [&](CellIndex first, std::uint32_t run) {
      uncovered.reset_range(first, first + run);
      covered.set_range(first, first + run);
    });
    boxes.push_back(box);
  }
}

}  // namespace

std::size_t append_boxes(const CellSet& cells, const BoxAxes& axes,
                         std::vector<std::uint8_t>& box_bytes) {
  // A box can span a trailing axis whole only if its cells fit an extent byte: the lowest level
  // is the first after the last axis that does not.
  std::uint32_t lowest = 1;
  for (std::uint32_t axis = 1; axis < axes.count; ++axis) {
    if (axes.cells[axis] > kMaxExtent) lowest = axis + 1;
  }
  // levels[d]: the set over the first d axes whose cells hold along all remaining axes.
  std::vector<CellSet> levels(axes.count + 1);
  levels[axes.count] = cells;
  for (std::uint32_t d = axes.count - 1; d >= lowest && d >= 1; --d) {
    levels[d] = cells_in_every_slice(levels[d + 1], axes.stride[d], axes.cells[d]);
  }
  std::vector<Box> boxes;
  for (std::uint32_t d = lowest; d <= axes.count; ++d) {
    if (!levels[d].any()) continue;
    std::uint32_t full_extents[kMaxJoints]{};
    for (std::uint32_t axis = d; axis < axes.count; ++axis) full_extents[axis] = axes.cells[axis];
    const CellSet covered = d == lowest ? CellSet(levels[d].cell_count())
                                        : repeat_slice(levels[d - 1], axes.cells[d - 1]);
    cover(levels[d], covered, leading_axes(axes, d), full_extents, boxes);
  }
  // A level's box starts on its lowest cell with coordinate 0 along the axes it spans whole, so
  // its start is the same cell index in the whole grid.
  std::stable_sort(boxes.begin(), boxes.end(),
                   [](const Box& a, const Box& b) { return a.start < b.start; });
  CellIndex previous_start = 0;
  for (const Box& box : boxes) {
    PixelToCellsTable::append_box(box_bytes, previous_start, box.start, box.extents, axes.count);
    previous_start = box.start;
  }
  return boxes.size();
}

}  // namespace safecell
