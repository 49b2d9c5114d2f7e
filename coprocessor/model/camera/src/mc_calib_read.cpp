#include <cmath>

#include "camera_checks.hpp"
#include "error_text.hpp"
#include "opencv_yaml_reader.hpp"
#include "safecell/camera/calibration_import.hpp"
#include "safecell/camera/camera_error.hpp"

namespace safecell {
namespace {

constexpr const char* kExpected = "an MC-Calib result (calibrated_cameras_data.yml)";
constexpr int kMaxCameras = 64;

McCalibCamera read_camera(const CalibrationReader& reader, const std::string& source, int index,
                          double units_m) {
  McCalibCamera camera;
  camera.index = index;
  CameraIntrinsics& intrinsics = camera.intrinsics;
  intrinsics.width_px = reader.image_size("img_width");
  intrinsics.height_px = reader.image_size("img_height");
  read_camera_matrix(reader, intrinsics);
  const YAML::Node type = reader.require("distortion_type", "0 (Brown: k1 k2 p1 p2 k3)");
  if (whole_number_of(type) != 0) {
    reader.fail("distortion_type", value_shown(type) +
                                       ", expected 0 (Brown: k1 k2 p1 p2 k3); a fisheye camera (1, "
                                       "Kannala-Brandt) is not supported");
  }
  intrinsics.distortion = read_distortion(reader, "distortion_vector");
  const Matrix pose = reader.matrix("camera_pose_matrix", {{4, 4}});
  for (int c = 0; c < 4; ++c) {
    const double expected = c == 3 ? 1.0 : 0.0;
    if (std::abs(pose.at(3, c) - expected) > 1e-9) {
      reader.fail("camera_pose_matrix", "entry (3, " + std::to_string(c) + ") is " +
                                            number_text(pose.at(3, c)) + ", expected " +
                                            number_text(expected) + " (a rigid transform)");
    }
  }
  Eigen::Matrix3d rotation;
  for (int r = 0; r < 3; ++r) {
    for (int c = 0; c < 3; ++c) rotation(r, c) = pose.at(r, c);
  }
  const Eigen::Vector3d translation_m =
      units_m * Eigen::Vector3d(pose.at(0, 3), pose.at(1, 3), pose.at(2, 3));
  const std::string prefix = "camera_" + std::to_string(index) + ".";
  check_camera_values(
      source,
      {prefix + "img_width", prefix + "img_height", prefix + "camera_matrix (fx)",
       prefix + "camera_matrix (fy)", prefix + "camera_matrix (cx)", prefix + "camera_matrix (cy)",
       prefix + "distortion_vector", prefix + "camera_pose_matrix (rotation)",
       prefix + "camera_pose_matrix (translation)"},
      intrinsics, rotation, translation_m);
  camera.camera_to_reference.linear() = rotation;
  camera.camera_to_reference.translation() = translation_m;
  return camera;
}

bool is_identity(const Eigen::Isometry3d& pose) {
  return pose.linear().isApprox(Eigen::Matrix3d::Identity(), 1e-6) &&
         pose.translation().norm() < 1e-6;
}

// The cell pose given with the file is camera 0's: MC-Calib's poses must then be relative to it.
// A group whose reference is another camera is named, not placed wrongly.
void check_reference_camera(const std::string& source, const std::vector<McCalibCamera>& cameras) {
  if (is_identity(cameras.front().camera_to_reference)) return;
  std::string reference = "none of the cameras has it";
  for (const McCalibCamera& camera : cameras) {
    if (is_identity(camera.camera_to_reference)) {
      reference = "camera_" + std::to_string(camera.index) + " has it: the group's reference";
      break;
    }
  }
  throw_camera_error(source, "camera_0: camera_pose_matrix",
                     "is not the identity, expected camera 0 to be the reference camera whose "
                     "cell pose is given (" +
                         reference + ")");
}

}  // namespace

std::vector<McCalibCamera> read_mc_calib_cameras(const std::filesystem::path& path,
                                                 double units_m) {
  const std::string source = path.string();
  if (!(units_m > 0.0 && units_m <= 1000.0)) {
    throw_camera_error(source, "(units)",
                       number_text(units_m) + " m per unit, expected a scale in (0, 1000]");
  }
  const CalibrationReader root(source, opencv_yaml_tree(path, kExpected));
  const YAML::Node count_node = root.require("nb_camera", "the number of cameras");
  const auto count = whole_number_of(count_node);
  if (!count || *count < 1 || *count > kMaxCameras) {
    root.fail("nb_camera",
              value_shown(count_node) + ", expected 1.." + std::to_string(kMaxCameras));
  }
  std::vector<McCalibCamera> cameras;
  for (int index = 0; index < static_cast<int>(*count); ++index) {
    const std::string key = "camera_" + std::to_string(index);
    std::string expected = "camera " + std::to_string(index);
    expected += " of nb_camera " + std::to_string(*count);
    const YAML::Node node = root.require(key.c_str(), expected);
    std::string where = source;
    where += ": " + key;
    cameras.push_back(read_camera(CalibrationReader(where, node), source, index, units_m));
  }
  check_reference_camera(source, cameras);
  return cameras;
}

PinholeCamera mc_calib_camera_in_cell(const McCalibCamera& camera,
                                      const Eigen::Isometry3d& cell_to_reference,
                                      std::string name) {
  return {std::move(name), camera.intrinsics,
          camera.camera_to_reference.inverse(Eigen::Isometry) * cell_to_reference};
}

}  // namespace safecell
