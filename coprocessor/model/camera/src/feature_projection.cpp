#include "safecell/camera/feature_projection.hpp"

#include <string>

#include "safecell/camera/camera_error.hpp"

namespace safecell {

std::optional<FeatureCell> project_to_feature_cell(const PinholeCamera& camera,
                                                   const FeatureGrid& grid,
                                                   const Eigen::Vector3d& point_cell_m) {
  const CameraIntrinsics& intrinsics = camera.intrinsics();
  if (grid.image_width_px() != intrinsics.width_px ||
      grid.image_height_px() != intrinsics.height_px) {
    throw_camera_error("camera '" + camera.name() + "'", "feature grid",
                       std::to_string(grid.columns()) + " x " + std::to_string(grid.rows()) +
                           " cells of " + std::to_string(grid.cell_width_px()) + " x " +
                           std::to_string(grid.cell_height_px()) + " px cover " +
                           std::to_string(grid.image_width_px()) + " x " +
                           std::to_string(grid.image_height_px()) + " px, expected the camera's " +
                           std::to_string(intrinsics.width_px) + " x " +
                           std::to_string(intrinsics.height_px) + " px image");
  }
  const auto pixel = camera.project(point_cell_m);
  if (!pixel) return std::nullopt;
  return grid.cell_of(*pixel);
}

}  // namespace safecell
