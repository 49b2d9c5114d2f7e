#include "safecell/lut/pixel_table_builder.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>

namespace safecell {
namespace {

constexpr std::uint32_t kMaxExtent = 255;  // one byte per extent

// Whether every row of the box (start, extents) lies in `cells`.
bool box_inside(const CellSet& cells, const BoxAxes& axes, CellIndex start,
                const std::uint32_t* extents) {
  bool inside = true;
  for_each_box_row(axes, start, extents, [&](CellIndex first, std::uint32_t run) {
    inside = inside && cells.all_in_range(first, first + run);
  });
  return inside;
}

}  // namespace

std::size_t append_boxes(const CellSet& cells, const BoxAxes& axes,
                         std::vector<std::uint8_t>& box_bytes) {
  CellSet remaining = cells;
  std::size_t boxes = 0;
  for (CellIndex start = remaining.next_set(0); start < remaining.cell_count();
       start = remaining.next_set(start)) {
    std::uint32_t coord[kMaxJoints]{};
    for (std::uint32_t axis = 0; axis < axes.count; ++axis) {
      coord[axis] = start / axes.stride[axis] % axes.cells[axis];
    }
    std::uint32_t extents[kMaxJoints]{};
    for (std::uint32_t axis = 0; axis < axes.count; ++axis) extents[axis] = 1;
    while (coord[0] + extents[0] < axes.cells[0] && extents[0] < kMaxExtent &&
           remaining.test(start + extents[0])) {
      ++extents[0];
    }
    for (std::uint32_t axis = 1; axis < axes.count; ++axis) {
      while (coord[axis] + extents[axis] < axes.cells[axis] && extents[axis] < kMaxExtent) {
        // The next layer along this axis: the box so far, moved by `extents[axis]` steps.
        std::uint32_t layer[kMaxJoints]{};
        std::copy(extents, extents + axes.count, layer);
        layer[axis] = 1;
        if (!box_inside(remaining, axes, start + extents[axis] * axes.stride[axis], layer)) break;
        ++extents[axis];
      }
    }
    for_each_box_row(axes, start, extents, [&](CellIndex first, std::uint32_t run) {
      remaining.reset_range(first, first + run);
    });
    for (int shift = 0; shift < 32; shift += 8) {
      box_bytes.push_back(static_cast<std::uint8_t>(start >> shift));
    }
    for (std::uint32_t axis = 0; axis < axes.count; ++axis) {
      box_bytes.push_back(static_cast<std::uint8_t>(extents[axis]));
    }
    ++boxes;
  }
  return boxes;
}

PixelToCellsTable build_pixel_to_cells_table(const CellToPixelsTable& cell_table,
                                             const CspaceGrid& grid, const PixelTableBuild& build,
                                             const ProgressCallback& progress) {
  if (cell_table.cell_count() != grid.cell_count()) {
    throw std::invalid_argument("LUT-1 has " + std::to_string(cell_table.cell_count()) +
                                " cells, the grid " + std::to_string(grid.cell_count()));
  }
  const BoxAxes axes = BoxAxes::of(grid);
  const int columns = cell_table.columns();
  const int rows = cell_table.rows();
  const std::size_t bytes_per_row = static_cast<std::size_t>(columns) *
                                    ((static_cast<std::size_t>(grid.cell_count()) + 63) / 64) * 8;
  const int band_rows = static_cast<int>(
      std::clamp<std::size_t>(build.memory_budget_bytes / std::max<std::size_t>(bytes_per_row, 1),
                              1, static_cast<std::size_t>(rows)));

  std::vector<std::uint64_t> offsets{0};
  std::vector<std::uint8_t> box_bytes;
  for (int band = 0; band < rows; band += band_rows) {
    const int band_end = std::min(rows, band + band_rows);
    const auto band_pixels =
        static_cast<std::size_t>(band_end - band) * static_cast<std::size_t>(columns);
    std::vector<CellSet> pixel_cells(band_pixels, CellSet(grid.cell_count()));
    // Gather: one feature row per chunk, so that no two threads write the same bitset.
    parallel_chunks(static_cast<std::size_t>(band_end - band), 1, build.threads,
                    [&](std::size_t, std::size_t begin, std::size_t) {
                      const int row = band + static_cast<int>(begin);
                      CellSet* row_cells =
                          pixel_cells.data() + begin * static_cast<std::size_t>(columns);
                      for (CellIndex cell = 0; cell < grid.cell_count(); ++cell) {
                        for (const auto& rect : cell_table.rects_of(cell)) {
                          if (rect.row0 > row || rect.row1 < row) continue;
                          for (int column = rect.col0; column <= rect.col1; ++column) {
                            row_cells[column].set(cell);
                          }
                        }
                      }
                    });
    // Cut every pixel's cells into boxes, in parallel, then append in pixel order.
    std::vector<std::vector<std::uint8_t>> pixel_boxes(band_pixels);
    std::vector<std::size_t> pixel_box_counts(band_pixels);
    parallel_chunks(
        band_pixels, 16, build.threads, [&](std::size_t, std::size_t begin, std::size_t end) {
          for (std::size_t pixel = begin; pixel < end; ++pixel) {
            pixel_box_counts[pixel] = append_boxes(pixel_cells[pixel], axes, pixel_boxes[pixel]);
            pixel_cells[pixel] = CellSet{};
          }
        });
    for (std::size_t pixel = 0; pixel < band_pixels; ++pixel) {
      offsets.push_back(offsets.back() + pixel_box_counts[pixel]);
      box_bytes.insert(box_bytes.end(), pixel_boxes[pixel].begin(), pixel_boxes[pixel].end());
    }
    if (progress) progress(static_cast<double>(band_end) / rows);
  }
  return PixelToCellsTable(grid, columns, rows, std::move(offsets), std::move(box_bytes));
}

}  // namespace safecell
