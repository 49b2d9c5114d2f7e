#pragma once
// Calibrations made with other tools, turned into this project's cameras. Neither format places
// a camera in the cell: a ROS camera_info file holds no pose, and MC-Calib's poses are relative
// to its reference camera. The cell pose comes from a pose file: this project's calibration
// format (calibration_file.hpp) with only its extrinsic keys, cell_to_camera_rvec (or
// cell_to_camera_rotation) and cell_to_camera_translation_m, e.g. from cv::solvePnP on markers
// at known places in the cell.
// Every reader throws CameraError naming the file, the key, the value and what was expected.

#include <Eigen/Geometry>
#include <filesystem>
#include <string>
#include <vector>

#include "safecell/camera/camera_intrinsics.hpp"
#include "safecell/camera/pinhole_camera.hpp"

namespace safecell {

// The extrinsic keys of a calibration file alone: x_camera = R x_cell + t (t in metres). Other
// keys are ignored.
[[nodiscard]] Eigen::Isometry3d read_cell_pose(const std::filesystem::path& path);

// A ROS sensor_msgs/CameraInfo YAML file (what camera_calibration writes): image_width,
// image_height, camera_matrix, distortion_model and distortion_coefficients. The plumb_bob model
// only (OpenCV's k1 k2 p1 p2 k3); the rectification and projection matrices are for rectified
// images and are not used (the service works on the raw frames).
[[nodiscard]] CameraIntrinsics read_ros_camera_info(const std::filesystem::path& path);

// One camera of an MC-Calib result file (calibrated_cameras_data.yml).
struct McCalibCamera {
  int index = 0;  // N of its camera_N key
  CameraIntrinsics intrinsics;
  // The camera's pose in the reference camera's frame: x_reference = pose * x_camera (MC-Calib
  // saves the inverse of its group's reference-to-camera transform), in metres.
  Eigen::Isometry3d camera_to_reference = Eigen::Isometry3d::Identity();
};

// Every camera of the file, in index order. units_m: metres per unit of the file's translations
// (MC-Calib's are in the unit of its board's square size: 0.001 for millimetres). The Brown
// model only (distortion_type 0); a fisheye camera (1) is refused.
[[nodiscard]] std::vector<McCalibCamera> read_mc_calib_cameras(const std::filesystem::path& path,
                                                               double units_m);

// An MC-Calib camera in the cell, its reference camera at `cell_to_reference` (x_reference =
// cell_to_reference * x_cell): cell_to_camera = camera_to_reference^-1 * cell_to_reference.
[[nodiscard]] PinholeCamera mc_calib_camera_in_cell(const McCalibCamera& camera,
                                                    const Eigen::Isometry3d& cell_to_reference,
                                                    std::string name);

}  // namespace safecell
