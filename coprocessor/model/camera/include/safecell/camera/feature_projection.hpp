#pragma once
// From a cell point straight to the feature cell that sees it.

#include <Eigen/Core>
#include <optional>

#include "safecell/camera/feature_grid.hpp"
#include "safecell/camera/pinhole_camera.hpp"

namespace safecell {

// The feature cell the point projects into; nullopt when the camera does not see it (behind the
// camera or outside the image). Throws CameraError when the grid does not cover exactly the
// camera's image.
[[nodiscard]] std::optional<FeatureCell> project_to_feature_cell(
    const PinholeCamera& camera, const FeatureGrid& grid, const Eigen::Vector3d& point_cell_m);

}  // namespace safecell
