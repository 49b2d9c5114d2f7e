#pragma once
// The look-up tables of one robot geometry and camera set-up: LUT-1 and LUT-2 of every camera,
// and the static-obstacle cells, stamped with the fingerprint of everything they were built
// from. Stored in one file (lut_file.hpp).

#include <cstdint>
#include <string>
#include <vector>

#include "safecell/lut/cell_set.hpp"
#include "safecell/lut/cell_to_pixels_table.hpp"
#include "safecell/lut/pixel_to_cells_table.hpp"

namespace safecell {

enum class LutSource : std::uint32_t { kModel = 1, kRecorded = 2 };

const char* to_string(LutSource source);

struct CameraLuts {
  std::string camera;
  // LUT-1; empty in a model-mode set (ModelSilhouettes computes it from the model).
  CellToPixelsTable cell_to_pixels;
  PixelToCellsTable pixel_to_cells;  // LUT-2
};

struct LutSet {
  // Hash of the grid, the robot's geometry, the cameras' calibration, the feature grid, the
  // static obstacles and the build settings; a set built from anything else is refused.
  std::uint64_t fingerprint = 0;
  std::uint64_t grid_fingerprint = 0;
  LutSource source = LutSource::kModel;
  int columns = 0;  // the feature grid
  int rows = 0;
  std::vector<CameraLuts> cameras;
  CellSet static_cells;
};

}  // namespace safecell
