// Calibrations from other tools. The ground truth is a pair of cameras placed in the cell; the
// files are written from them the way ROS's camera_calibration and MC-Calib write theirs
// (MC-Calib: camera_pose_matrix is the camera's pose in the reference camera's frame, in the
// board's unit), and the imported cameras must project cell points where the originals do. The
// negative controls read the same file with the pose taken the other way round, or in the wrong
// unit, and must land far off.

#include "safecell/camera/calibration_import.hpp"

#include <gtest/gtest.h>

#include <fstream>
#include <opencv2/core/persistence.hpp>
#include <random>

#include "safecell/camera/calibration_file.hpp"
#include "safecell/camera/camera_error.hpp"
#include "safecell/test/scratch_folder.hpp"

namespace safecell {
namespace {

namespace fs = std::filesystem;

CameraIntrinsics lens(double fx, double k1) {
  CameraIntrinsics k;
  k.fx_px = fx;
  k.fy_px = fx * 1.01;
  k.cx_px = 350.2;
  k.cy_px = 290.7;
  k.width_px = 704;
  k.height_px = 576;
  k.distortion = {k1, 0.03, 0.001, -0.0005, 0.0};
  return k;
}

PinholeCamera placed(const std::string& name, const CameraIntrinsics& intrinsics,
                     const Eigen::Vector3d& position_m) {
  const PinholeCamera looking = PinholeCamera::look_at(name, position_m, {0.0, 0.0, 0.8},
                                                       Eigen::Vector3d::UnitZ(), 1.3, 704, 576);
  return {name, intrinsics, looking.cell_to_camera()};
}

cv::Mat as_mat(const Eigen::Matrix4d& m) {
  cv::Mat out(4, 4, CV_64F);
  for (int r = 0; r < 4; ++r) {
    for (int c = 0; c < 4; ++c) out.at<double>(r, c) = m(r, c);
  }
  return out;
}

cv::Mat camera_matrix(const CameraIntrinsics& k) {
  return (cv::Mat_<double>(3, 3) << k.fx_px, 0, k.cx_px, 0, k.fy_px, k.cy_px, 0, 0, 1);
}

// The cameras as MC-Calib saves them, camera `reference` the reference (0 unless said),
// translations in millimetres.
void write_mc_calib(const fs::path& file, const std::vector<PinholeCamera>& cameras,
                    std::size_t reference = 0) {
  cv::FileStorage out(file.string(), cv::FileStorage::WRITE);
  out << "nb_camera" << static_cast<int>(cameras.size());
  const Eigen::Isometry3d cell_to_reference = cameras[reference].cell_to_camera();
  for (std::size_t i = 0; i < cameras.size(); ++i) {
    const CameraIntrinsics& k = cameras[i].intrinsics();
    // MC-Calib's group holds reference -> camera; it saves the inverse.
    const Eigen::Isometry3d reference_to_camera =
        cameras[i].cell_to_camera() * cell_to_reference.inverse();
    Eigen::Matrix4d saved = reference_to_camera.inverse().matrix();
    saved.block<3, 1>(0, 3) *= 1000.0;
    out << "camera_" + std::to_string(i) << "{";
    out << "camera_matrix" << camera_matrix(k);
    out << "distortion_vector"
        << (cv::Mat_<double>(1, 5) << k.distortion.k1, k.distortion.k2, k.distortion.p1,
            k.distortion.p2, k.distortion.k3);
    out << "distortion_type" << 0 << "camera_group" << 0;
    out << "img_width" << k.width_px << "img_height" << k.height_px;
    out << "camera_pose_matrix" << as_mat(saved) << "}";
  }
}

// The largest distance between the pixels two cameras project cell points to (points in front
// of both, inside the first's image).
double worst_pixel_error(const PinholeCamera& truth, const PinholeCamera& imported) {
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> xy(-1.8, 1.8);
  std::uniform_real_distribution<double> z(0.0, 2.0);
  double worst = 0.0;
  int compared = 0;
  for (int i = 0; i < 2000 && compared < 200; ++i) {
    const Eigen::Vector3d point(xy(rng), xy(rng), z(rng));
    const auto expected = truth.project(point);
    if (!expected || !truth.in_image(*expected)) continue;
    const auto got = imported.project(point);
    worst = got ? std::max(worst, (*got - *expected).norm()) : 1e9;
    ++compared;
  }
  EXPECT_EQ(compared, 200);
  return worst;
}

TEST(McCalibImport, EveryCameraProjectsAsTheOriginalOnceItsReferenceIsPlacedInTheCell) {
  const test::ScratchFolder folder;
  const std::vector<PinholeCamera> cameras{placed("a", lens(460, -0.12), {1.9, 1.9, 2.9}),
                                           placed("b", lens(430, -0.08), {-1.9, 1.9, 2.8}),
                                           placed("c", lens(470, 0.05), {-1.9, -1.9, 3.0})};
  write_mc_calib(folder.path() / "calibrated_cameras_data.yml", cameras);
  // The reference camera's cell pose, as a pose file (the extrinsic keys of a calibration file).
  write_camera_calibration(folder.path() / "reference_pose.yaml", cameras[0]);
  const Eigen::Isometry3d cell_to_reference = read_cell_pose(folder.path() / "reference_pose.yaml");

  const auto imported = read_mc_calib_cameras(folder.path() / "calibrated_cameras_data.yml", 0.001);
  ASSERT_EQ(imported.size(), 3U);
  for (std::size_t i = 0; i < imported.size(); ++i) {
    EXPECT_EQ(imported[i].index, static_cast<int>(i));
    const PinholeCamera camera = mc_calib_camera_in_cell(imported[i], cell_to_reference, "x");
    EXPECT_LT(worst_pixel_error(cameras[i], camera), 1e-6) << "camera " << i;
  }

  // Negative controls: the pose the other way round, or the file's unit taken as metres.
  McCalibCamera reversed = imported[1];
  reversed.camera_to_reference = reversed.camera_to_reference.inverse();
  EXPECT_GT(
      worst_pixel_error(cameras[1], mc_calib_camera_in_cell(reversed, cell_to_reference, "x")),
      10.0);
  const auto in_metres = read_mc_calib_cameras(folder.path() / "calibrated_cameras_data.yml", 1.0);
  EXPECT_GT(
      worst_pixel_error(cameras[1], mc_calib_camera_in_cell(in_metres[1], cell_to_reference, "x")),
      10.0);
}

// The cell pose given is camera 0's: a group whose reference is another camera is named.
TEST(McCalibImport, AGroupWhoseReferenceIsNotCameraZeroIsNamed) {
  const test::ScratchFolder folder;
  const fs::path file = folder.path() / "calibrated_cameras_data.yml";
  const std::vector<PinholeCamera> cameras{placed("a", lens(460, -0.12), {1.9, 1.9, 2.9}),
                                           placed("b", lens(430, -0.08), {-1.9, 1.9, 2.8})};
  write_mc_calib(file, cameras, 1);
  try {
    (void)read_mc_calib_cameras(file, 0.001);
    ADD_FAILURE() << "a group with camera 1 as its reference was taken";
  } catch (const CameraError& error) {
    EXPECT_NE(std::string(error.what()).find("camera_1 has it: the group's reference"),
              std::string::npos)
        << error.what();
  }
  write_mc_calib(file, cameras, 0);  // the control
  EXPECT_EQ(read_mc_calib_cameras(file, 0.001).size(), 2U);
}

TEST(McCalibImport, AFisheyeCameraAndAMissingCameraAreNamed) {
  const test::ScratchFolder folder;
  const fs::path file = folder.path() / "calibrated_cameras_data.yml";
  write_mc_calib(file, {placed("a", lens(460, -0.12), {1.9, 1.9, 2.9})});
  std::string text;
  {
    std::ifstream in(file);
    text.assign(std::istreambuf_iterator<char>(in), {});
  }
  const auto rewrite = [&](const std::string& from, const std::string& to) {
    std::string changed = text;
    changed.replace(changed.find(from), from.size(), to);
    std::ofstream(file) << changed;
  };
  rewrite("distortion_type: 0", "distortion_type: 1");
  try {
    (void)read_mc_calib_cameras(file, 0.001);
    ADD_FAILURE() << "a fisheye camera was taken";
  } catch (const CameraError& error) {
    EXPECT_NE(std::string(error.what()).find("camera_0: distortion_type: 1"), std::string::npos)
        << error.what();
  }
  rewrite("nb_camera: 1", "nb_camera: 2");
  try {
    (void)read_mc_calib_cameras(file, 0.001);
    ADD_FAILURE() << "a missing camera was not noticed";
  } catch (const CameraError& error) {
    EXPECT_NE(std::string(error.what()).find("camera_1: missing"), std::string::npos)
        << error.what();
  }
  EXPECT_THROW((void)read_mc_calib_cameras(file, 0.0), CameraError);
}

constexpr const char* kRosCameraInfo = R"(image_width: 704
image_height: 576
camera_name: cam0
camera_matrix:
  rows: 3
  cols: 3
  data: [458.7, 0, 351.5, 0, 459.1, 287.25, 0, 0, 1]
distortion_model: plumb_bob
distortion_coefficients:
  rows: 1
  cols: 5
  data: [-0.1, 0.02, 0.001, -0.002, 0.003]
rectification_matrix:
  rows: 3
  cols: 3
  data: [1, 0, 0, 0, 1, 0, 0, 0, 1]
projection_matrix:
  rows: 3
  cols: 4
  data: [458.7, 0, 351.5, 0, 0, 459.1, 287.25, 0, 0, 0, 1, 0]
)";

TEST(RosCameraInfoImport, TheLensIsReadAsWritten) {
  const test::ScratchFolder folder;
  std::ofstream(folder.path() / "cam0.yaml") << kRosCameraInfo;
  const CameraIntrinsics k = read_ros_camera_info(folder.path() / "cam0.yaml");
  EXPECT_EQ(k.width_px, 704);
  EXPECT_EQ(k.height_px, 576);
  EXPECT_DOUBLE_EQ(k.fx_px, 458.7);
  EXPECT_DOUBLE_EQ(k.fy_px, 459.1);
  EXPECT_DOUBLE_EQ(k.cx_px, 351.5);
  EXPECT_DOUBLE_EQ(k.cy_px, 287.25);
  EXPECT_DOUBLE_EQ(k.distortion.k1, -0.1);
  EXPECT_DOUBLE_EQ(k.distortion.p2, -0.002);
  EXPECT_DOUBLE_EQ(k.distortion.k3, 0.003);
}

TEST(RosCameraInfoImport, WhatCannotBeUsedIsNamed) {
  const test::ScratchFolder folder;
  const fs::path file = folder.path() / "cam0.yaml";
  const auto refused = [&](const std::string& from, const std::string& to) -> std::string {
    std::string text = kRosCameraInfo;
    text.replace(text.find(from), from.size(), to);
    std::ofstream(file) << text;
    try {
      (void)read_ros_camera_info(file);
    } catch (const CameraError& error) {
      return error.what();
    }
    return "(taken)";
  };
  EXPECT_NE(refused("plumb_bob", "equidistant").find("distortion_model: 'equidistant'"),
            std::string::npos);
  EXPECT_NE(refused("[458.7, 0, 351.5,", "[458.7, 0.5, 351.5,").find("camera_matrix"),
            std::string::npos);
  EXPECT_NE(refused("[-0.1, 0.02, 0.001, -0.002, 0.003]", "[-0.1, 0.02]")
                .find("distortion_coefficients: data holds 2 numbers"),
            std::string::npos);
  EXPECT_NE(refused("image_width: 704", "image_width: -4").find("image_width"), std::string::npos);
  EXPECT_NE(refused("image_width: 704", "image_width: [").find("not valid YAML"),
            std::string::npos);
  EXPECT_THROW((void)read_ros_camera_info(folder.path() / "none.yaml"), CameraError);
  // A matrix that is a number (yaml-cpp threw its own exception past the reader: exit 70), a
  // misspelt or repeated key, a file nested deeper than any camera_info: each named.
  EXPECT_NE(refused("camera_matrix:\n  rows: 3\n  cols: 3\n  data: [458.7, 0, 351.5, 0, 459.1, "
                    "287.25, 0, 0, 1]",
                    "camera_matrix: 3")
                .find("camera_matrix: expected a mapping"),
            std::string::npos);
  EXPECT_NE(refused("image_height", "image_hieght").find("image_hieght: unknown key"),
            std::string::npos);
  EXPECT_NE(refused("  rows: 1\n", "  rows: 1\n  rows: 1\n").find("given twice"),
            std::string::npos);
  EXPECT_NE(refused("  rows: 1\n", "  rowz: 1\n").find("unknown key 'rowz'"), std::string::npos);
  EXPECT_NE(
      refused("camera_name: cam0", "camera_name: " + std::string(40, '[') + std::string(40, ']'))
          .find("nested deeper than 16"),
      std::string::npos);
}

}  // namespace
}  // namespace safecell
