#include "safecell/cell/cell_scene.hpp"

#include <cmath>
#include <numbers>
#include <set>

#include "safecell/camera/calibration_file.hpp"
#include "safecell/camera/camera_error.hpp"
#include "safecell/cell/cell_error.hpp"

namespace safecell {
namespace {

constexpr double kRadPerDeg = std::numbers::pi / 180.0;

Eigen::Vector3d vector_of(const std::array<double, 3>& values) {
  return {values[0], values[1], values[2]};
}

std::string camera_path(std::size_t index) { return "cameras[" + std::to_string(index) + "]"; }

PinholeCamera camera_of(const CameraConfig& camera, std::size_t index) {
  try {
    if (camera.look_at) {
      const LookAtConfig& placement = *camera.look_at;
      return PinholeCamera::look_at(camera.name, vector_of(placement.position_m),
                                    vector_of(placement.target_m), Eigen::Vector3d::UnitZ(),
                                    placement.horizontal_fov_deg * kRadPerDeg, placement.width_px,
                                    placement.height_px);
    }
    return read_camera_calibration(camera.calibration, camera.name);
  } catch (const CameraError& error) {
    throw_cell_error(camera.at, camera_path(index) + (camera.look_at ? ".look_at" : ".calibration"),
                     error.what());
  }
}

}  // namespace

std::vector<PinholeCamera> cell_cameras(const CellConfig& cell) {
  std::vector<PinholeCamera> cameras;
  std::set<std::string> names;
  for (std::size_t i = 0; i < cell.cameras.size(); ++i) {
    const CameraConfig& camera = cell.cameras[i];
    if (!names.insert(camera.name).second) {
      throw_cell_error(camera.at, camera_path(i) + ".name",
                       "'" + camera.name + "' is used by an earlier camera; names must differ");
    }
    cameras.push_back(camera_of(camera, i));
  }
  return cameras;
}

FeatureGrid cell_feature_grid(const CellConfig& cell, const std::vector<PinholeCamera>& cameras) {
  const FeatureGridConfig& grid = cell.feature_grid;
  const std::string value =
      "[" + std::to_string(grid.columns) + " x " + std::to_string(grid.rows) + "]";
  if (cameras.empty()) {
    return FeatureGrid::tiling(grid.columns * 11, grid.rows * 9, grid.columns, grid.rows);
  }
  FeatureGrid tiling;
  for (const auto& camera : cameras) {
    try {
      tiling = FeatureGrid::tiling(camera.intrinsics().width_px, camera.intrinsics().height_px,
                                   grid.columns, grid.rows);
    } catch (const CameraError& error) {
      throw_cell_error(grid.at.line > 0 ? grid.at : cell.cameras_at, "feature_grid",
                       "value " + value + " for camera '" + camera.name() + "': " + error.what());
    }
  }
  return tiling;
}

std::vector<PlacedShape> cell_obstacles(const CellConfig& cell) {
  std::vector<PlacedShape> boxes;
  for (std::size_t i = 0; i < cell.obstacles.size(); ++i) {
    const BoxObstacleConfig& box = cell.obstacles[i];
    const std::string path = "obstacles[" + std::to_string(i) + "]";
    for (const double size : box.size_m) {
      if (!(std::isfinite(size) && size > 0.0)) {
        throw_cell_error(box.at, path + ".size_m",
                         "value " + std::to_string(size) + ", expected edge lengths above 0 m");
      }
    }
    const Eigen::Vector3d centre = vector_of(box.centre_m);
    if (!centre.allFinite() || !std::isfinite(box.yaw_deg)) {
      throw_cell_error(box.at, path, "centre_m and yaw_deg must be finite numbers");
    }
    Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
    pose.translation() = centre;
    pose.linear() =
        Eigen::AngleAxisd(box.yaw_deg * kRadPerDeg, Eigen::Vector3d::UnitZ()).toRotationMatrix();
    boxes.push_back(PlacedShape{Box{vector_of(box.size_m)}, pose});
  }
  return boxes;
}

}  // namespace safecell
