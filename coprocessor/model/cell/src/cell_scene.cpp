#include "safecell/cell/cell_scene.hpp"

#include <cmath>
#include <numbers>
#include <set>
#include <sstream>

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

// Where a camera of the cell can hang: over the floor, at most this far above the cell's height or
// outside its walls (cameras on a fence or a gantry beside the cell). A pose file holding the
// camera-to-cell transform where cell-to-camera belongs puts the camera elsewhere.
constexpr double kAboveCeiling_m = 1.0;
constexpr double kOutsideWalls_m = 2.0;

void check_camera_place(const CellConfig& cell, std::size_t index, const PinholeCamera& camera) {
  const Eigen::Vector3d at = camera.position_m();
  const double half_x = cell.size_m[0] / 2.0 + kOutsideWalls_m;
  const double half_y = cell.size_m[1] / 2.0 + kOutsideWalls_m;
  const double top = cell.size_m[2] + kAboveCeiling_m;
  if (at.z() > 0.0 && at.z() <= top && std::abs(at.x()) <= half_x && std::abs(at.y()) <= half_y) {
    return;
  }
  std::ostringstream problem;
  problem << "'" << camera.name() << "' has its optical centre at (" << at.x() << ", " << at.y()
          << ", " << at.z() << ") m, outside where a camera of this " << cell.size_m[0] << " x "
          << cell.size_m[1] << " x " << cell.size_m[2]
          << " m cell can hang (above the floor, at most " << kAboveCeiling_m
          << " m above its height and " << kOutsideWalls_m
          << " m outside its walls); does its pose file hold camera-to-cell instead of "
             "cell-to-camera?";
  throw_cell_error(cell.cameras[index].at, camera_path(index), problem.str());
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
    check_camera_place(cell, i, cameras.back());
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
  // One feature grid and one set of tables serve every camera: their images must be alike.
  const CameraIntrinsics& first = cameras.front().intrinsics();
  for (std::size_t i = 1; i < cameras.size(); ++i) {
    const CameraIntrinsics& in = cameras[i].intrinsics();
    if (in.width_px != first.width_px || in.height_px != first.height_px) {
      throw_cell_error(cell.cameras[i].at, camera_path(i),
                       "'" + cameras[i].name() + "' gives " + std::to_string(in.width_px) + " x " +
                           std::to_string(in.height_px) + " px images, but '" +
                           cameras.front().name() + "' gives " + std::to_string(first.width_px) +
                           " x " + std::to_string(first.height_px) +
                           " px; expected every camera of a cell to give images of one size");
    }
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
