#pragma once
// The look-up tables of one robot geometry and camera set-up: LUT-1 and LUT-2 of every camera,
// and the static-obstacle cells, stamped with the fingerprint of everything they were built
// from. Stored in one file (lut_file.hpp).

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "safecell/cellsets/cell_set.hpp"
#include "safecell/robot/robot_parts.hpp"
#include "safecell/tables/cell_to_pixels_table.hpp"
#include "safecell/tables/neighbour.hpp"
#include "safecell/tables/pixel_to_cells_table.hpp"

namespace safecell {

enum class LutSource : std::uint32_t { kModel = 1, kRecorded = 2 };

const char* to_string(LutSource source);

// LUT-2 of one robot part (robot_parts.hpp) in one camera: the C-space cells in which that part
// can cover each feature cell. Fusion votes per part.
struct PartLuts {
  PixelToCellsTable pixel_to_cells;  // LUT-2
  // LUT-2 of blocks of pixels: pixel_blocks[l - 1] for blocks of 2^l x 2^l
  // (pixel_table_builder.hpp).
  std::vector<PixelToCellsTable> pixel_blocks;
  // What each entry adds to its left or upper neighbour, per pyramid level: [n][0] for the
  // pixels, [n][l] for the blocks of 2^l x 2^l (pixel_table_builder.hpp). Empty where not built:
  // fusion then adds whole entries.
  std::array<std::vector<PixelToCellsTable>, kNeighbourCount> differences;
  // (cell, feature cell) pairs the part's tables hold: what the paper's uncompressed layout
  // stores.
  std::uint64_t covered_pairs = 0;

  // The whole entries of pyramid level `level`: the pixels (0) or the blocks of 2^level a side.
  // Precondition: level <= pixel_blocks.size().
  [[nodiscard]] const PixelToCellsTable& entries_of_level(std::size_t level) const {
    return level == 0 ? pixel_to_cells : pixel_blocks[level - 1];
  }
  // Bytes of LUT-2 with its block levels and differences.
  [[nodiscard]] std::size_t pixel_table_bytes() const;
};

struct CameraLuts {
  std::string camera;
  // LUT-1 of the whole robot; empty in a model-mode set (ModelSilhouettes computes it from the
  // model).
  CellToPixelsTable cell_to_pixels;
  std::vector<PartLuts> parts;  // one per LutSet::parts, in that order

  // Bytes of every part's LUT-2 with block levels and differences.
  [[nodiscard]] std::size_t pixel_table_bytes() const;
  // Pairs of every part.
  [[nodiscard]] std::uint64_t covered_pairs() const;
};

// Bytes of the paper's uncompressed layout for one camera: LUT-1 with a 2-byte pixel number per
// pair and LUT-2 with a 4-byte cell number per pair (more than 65536 cells), plus an 8-byte offset
// per cell and per pixel.
[[nodiscard]] std::uint64_t uncompressed_bytes(std::uint64_t covered_pairs,
                                               std::uint32_t cell_count, std::size_t pixel_count);

struct LutSet {
  // Hash of the grid, the robot's geometry, the cameras' calibration, the feature grid, the
  // static obstacles and the build settings; a set built from anything else is refused.
  std::uint64_t fingerprint = 0;
  std::uint64_t grid_fingerprint = 0;
  LutSource source = LutSource::kModel;
  int columns = 0;  // the feature grid
  int rows = 0;
  // The robot parts the cameras vote on, each with its own LUT-2 (one, the whole robot, in a
  // recorded set).
  std::vector<RobotPart> parts;
  std::vector<CameraLuts> cameras;
  CellSet static_cells;
};

}  // namespace safecell
