#include <Eigen/Geometry>
#include <cmath>
#include <initializer_list>
#include <tuple>
#include <utility>
#include <vector>

#include "camera_checks.hpp"
#include "error_text.hpp"
#include "opencv_yaml_reader.hpp"
#include "safecell/camera/calibration_file.hpp"
#include "safecell/camera/calibration_import.hpp"
#include "safecell/camera/camera_error.hpp"

namespace safecell {
namespace {

Eigen::Isometry3d cell_pose_of(const CalibrationReader& reader, const std::string& source,
                               const CameraIntrinsics& intrinsics, const CameraFieldNames& names) {
  const auto [rotation, rotation_key] = read_rotation(reader);
  const Matrix t = reader.matrix(kTranslationKey, {{3, 1}, {1, 3}});
  Eigen::Isometry3d cell_to_camera = Eigen::Isometry3d::Identity();
  cell_to_camera.linear() = rotation;
  cell_to_camera.translation() = Eigen::Vector3d(t.values[0], t.values[1], t.values[2]);
  CameraFieldNames named = names;
  named.rotation = rotation_key;
  named.translation = kTranslationKey;
  // The same checks as the camera's own, so the message names this file and its keys.
  check_camera_values(source, named, intrinsics, rotation, cell_to_camera.translation());
  return cell_to_camera;
}

PinholeCamera read_camera(const CalibrationReader& reader, const std::string& source,
                          std::string name) {
  reader.refuse_unknown_keys({"image_width", "image_height", "camera_matrix",
                              "distortion_coefficients", kRotationKey, kRvecKey, kTranslationKey,
                              // What OpenCV's calibration programs write beside: not read.
                              "calibration_time", "nframes", "nr_of_frames", "board_width",
                              "board_height", "square_size", "aspect_ratio", "fix_aspect_ratio",
                              "flags", "avg_reprojection_error", "per_view_reprojection_errors",
                              "extrinsic_parameters", "image_points", "grid_points"});
  CameraIntrinsics intrinsics;
  intrinsics.width_px = reader.image_size("image_width");
  intrinsics.height_px = reader.image_size("image_height");
  read_camera_matrix(reader, intrinsics);
  intrinsics.distortion = read_distortion(reader, "distortion_coefficients");
  const Eigen::Isometry3d cell_to_camera =
      cell_pose_of(reader, source, intrinsics,
                   {"image_width", "image_height", "camera_matrix (fx)", "camera_matrix (fy)",
                    "camera_matrix (cx)", "camera_matrix (cy)", "distortion_coefficients", "", ""});
  return {std::move(name), intrinsics, cell_to_camera};
}

}  // namespace

PinholeCamera read_camera_calibration(const std::filesystem::path& path, std::string name) {
  const std::string source = path.string();
  const CalibrationReader reader(source, opencv_yaml_tree(path, "an OpenCV YAML calibration"));
  return read_camera(reader, source, std::move(name));
}

Eigen::Isometry3d read_cell_pose(const std::filesystem::path& path) {
  const std::string source = path.string();
  const std::string expected = "an OpenCV YAML pose (cell_to_camera_rvec or _rotation, and " +
                               std::string(kTranslationKey) + ")";
  const CalibrationReader reader(source, opencv_yaml_tree(path, expected));
  // Intrinsics that pass the checks: only the pose's own values are checked here.
  CameraIntrinsics any_lens;
  any_lens.fx_px = any_lens.fy_px = 100.0;
  any_lens.cx_px = any_lens.cy_px = 50.0;
  any_lens.width_px = any_lens.height_px = 100;
  return cell_pose_of(reader, source, any_lens, {});
}

}  // namespace safecell
