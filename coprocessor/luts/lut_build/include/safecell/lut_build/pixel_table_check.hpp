#pragma once
// LUT-2 of a model-mode set against a direct computation, on a sample of C-space cells: in every
// camera and robot part, the feature cells whose entry names a sampled cell must be exactly the
// cell's silhouette as the robot model gives it (ModelSilhouettes: the part's balls over the cell
// projected into the camera), each block of the pyramid must name it exactly when one of its
// pixels' silhouettes holds it, and each difference entry must name only cells of its own entry
// and, with its neighbour's cells, all of them.
//
// The decoding is this file's own (the strips' line runs, mapped to cells through the line
// levels), not fusion's word loops: a check of a fine grid's tables that fusion cannot afford to
// build densely (`safecell luts build --verify-cells`).

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "safecell/compute/parallel_chunks.hpp"
#include "safecell/silhouettes/model_silhouettes.hpp"
#include "safecell/tables/lut_set.hpp"

namespace safecell {

enum class PixelTableEntry : std::uint8_t { kCells, kLeftDifference, kUpperDifference };

[[nodiscard]] const char* to_string(PixelTableEntry entry);

// One (entry, cell) pair that disagrees with the silhouettes.
struct PixelTableMismatch {
  std::size_t camera = 0;
  std::size_t part = 0;
  int level = 0;  // 0: pixels; l: blocks of 2^l x 2^l pixels
  PixelTableEntry entry = PixelTableEntry::kCells;
  int column = 0;  // of the level's grid of blocks
  int row = 0;
  CellIndex cell = 0;
  bool named = false;  // whether the entry names the cell (the silhouettes say the opposite)
};

struct PixelTableCheck {
  std::size_t cells = 0;         // sampled cells
  std::uint64_t entries = 0;     // entries decoded
  std::uint64_t pairs = 0;       // (entry, sampled cell) pairs compared
  std::uint64_t mismatches = 0;  // of them, wrong
  // The table's first kMaxReported (fewer when there are fewer), in table order: camera, part,
  // level, block, entry kind, cell. The same whatever the thread count.
  std::vector<PixelTableMismatch> first_mismatches;
  static constexpr std::size_t kMaxReported = 16;

  [[nodiscard]] bool passed() const { return mismatches == 0; }
};

// One line per reported mismatch, naming the camera, part, level, entry, block and cell.
[[nodiscard]] std::string describe(const PixelTableMismatch& mismatch, const LutSet& luts);

// Throws std::invalid_argument when the set is not a model-mode set of the silhouettes' grid,
// cameras and parts, or a sampled cell is outside the grid.
[[nodiscard]] PixelTableCheck check_pixel_tables(const LutSet& luts,
                                                 const ModelSilhouettes& silhouettes,
                                                 std::vector<CellIndex> sample, unsigned threads,
                                                 const ProgressCallback& progress = {});

}  // namespace safecell
