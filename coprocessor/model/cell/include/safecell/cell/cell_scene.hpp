#pragma once
// The cell's cameras and static obstacles, built from the cell file and checked for sense.

#include <vector>

#include "safecell/camera/feature_grid.hpp"
#include "safecell/camera/pinhole_camera.hpp"
#include "safecell/cell/cell_config.hpp"
#include "safecell/geometry/shape.hpp"

namespace safecell {

// Reads calibration files and places look-at cameras. Throws CellError naming the camera entry:
// an unreadable or invalid calibration, an impossible placement, a repeated name.
std::vector<PinholeCamera> cell_cameras(const CellConfig& cell);

// The feature grid every camera's image is cut into. Throws CellError when the grid does not
// tile a camera's image exactly.
FeatureGrid cell_feature_grid(const CellConfig& cell, const std::vector<PinholeCamera>& cameras);

// Boxes as placed shapes in the cell frame. Throws CellError for sizes that are not positive and
// finite, or a centre that is not finite.
std::vector<PlacedShape> cell_obstacles(const CellConfig& cell);

}  // namespace safecell
