// `safecell camera import`: a ROS camera_info file and an MC-Calib result become calibration files
// a cell file can name; the written camera must be the lens of the imported file at the pose
// file's place (read back through the project's own reader).

#include <gtest/gtest.h>

#include <fstream>

#include "cli_run.hpp"
#include "coarse_cell.hpp"
#include "safecell/camera/calibration_file.hpp"

namespace safecell {
namespace {

namespace fs = std::filesystem;

constexpr const char* kPose = R"(%YAML:1.0
---
cell_to_camera_rvec: !!opencv-matrix
   rows: 3
   cols: 1
   dt: d
   data: [ 2.2, -0.9, 0.4 ]
cell_to_camera_translation_m: !!opencv-matrix
   rows: 3
   cols: 1
   dt: d
   data: [ 0.1, 0.5, 3.4 ]
)";

constexpr const char* kRos = R"(image_width: 640
image_height: 480
camera_name: left
camera_matrix: {rows: 3, cols: 3, data: [500, 0, 320.5, 0, 501, 240.5, 0, 0, 1]}
distortion_model: plumb_bob
distortion_coefficients: {rows: 1, cols: 5, data: [-0.2, 0.05, 0, 0, 0]}
)";

// One camera, the reference itself (identity pose), as MC-Calib writes it.
constexpr const char* kMcCalib = R"(%YAML:1.0
---
nb_camera: 1
camera_0:
   camera_matrix: !!opencv-matrix
      rows: 3
      cols: 3
      dt: d
      data: [ 500., 0., 320.5, 0., 501., 240.5, 0., 0., 1. ]
   distortion_vector: !!opencv-matrix
      rows: 1
      cols: 5
      dt: d
      data: [ -0.2, 0.05, 0., 0., 0. ]
   distortion_type: 0
   camera_group: 0
   img_width: 640
   img_height: 480
   camera_pose_matrix: !!opencv-matrix
      rows: 4
      cols: 4
      dt: d
      data: [ 1., 0., 0., 0., 0., 1., 0., 0., 0., 0., 1., 0., 0., 0., 0., 1. ]
)";

void expect_camera(const PinholeCamera& camera) {
  EXPECT_EQ(camera.intrinsics().width_px, 640);
  EXPECT_DOUBLE_EQ(camera.intrinsics().fy_px, 501.0);
  EXPECT_DOUBLE_EQ(camera.intrinsics().distortion.k1, -0.2);
  EXPECT_NEAR(camera.cell_to_camera().translation().y(), 0.5, 1e-12);
  const Eigen::AngleAxisd rotation(camera.cell_to_camera().linear());
  EXPECT_NEAR((rotation.angle() * rotation.axis() - Eigen::Vector3d(2.2, -0.9, 0.4)).norm(), 0.0,
              1e-9);
}

TEST(CameraImportCommand, RosAndMcCalibFilesBecomeCalibrationFiles) {
  const test::ScratchFolder scratch("safecell-camera-import");
  std::ofstream(scratch.path() / "pose.yaml") << kPose;
  std::ofstream(scratch.path() / "left.yaml") << kRos;
  std::ofstream(scratch.path() / "rig.yml") << kMcCalib;

  const auto ros =
      test::safecell_cli({"camera", "import", "--ros", (scratch.path() / "left.yaml").string(),
                          "--pose", (scratch.path() / "pose.yaml").string(), "--name", "left",
                          "--out", (scratch.path() / "left_cell.yaml").string()});
  ASSERT_EQ(ros.exit_code, 0) << ros.err;
  EXPECT_NE(ros.out.find("camera 'left', 640 x 480 px"), std::string::npos) << ros.out;
  expect_camera(read_camera_calibration(scratch.path() / "left_cell.yaml", "left"));

  std::vector<std::string> rig_arguments{"camera",     "import",
                                         "--mc-calib", (scratch.path() / "rig.yml").string(),
                                         "--pose",     (scratch.path() / "pose.yaml").string(),
                                         "--out",      (scratch.path() / "rig").string()};
  // MC-Calib's unit is never guessed.
  const auto no_unit = test::safecell_cli(rig_arguments);
  EXPECT_EQ(no_unit.exit_code, kExitBadInput);
  EXPECT_NE(no_unit.err.find("--units-m"), std::string::npos) << no_unit.err;
  EXPECT_FALSE(fs::exists(scratch.path() / "rig"));
  rig_arguments.insert(rig_arguments.end(), {"--units-m", "0.001"});
  const auto rig = test::safecell_cli(rig_arguments);
  ASSERT_EQ(rig.exit_code, 0) << rig.err;
  expect_camera(read_camera_calibration(scratch.path() / "rig" / "cam0.yaml", "cam0"));
}

TEST(CameraImportCommand, BadInputIsNamed) {
  const test::ScratchFolder scratch("safecell-camera-import-bad");
  std::ofstream(scratch.path() / "pose.yaml") << kPose;
  std::ofstream(scratch.path() / "left.yaml") << "image_width: 640\n";
  const auto missing_key = test::safecell_cli(
      {"camera", "import", "--ros", (scratch.path() / "left.yaml").string(), "--pose",
       (scratch.path() / "pose.yaml").string(), "--out", (scratch.path() / "x.yaml").string()});
  EXPECT_EQ(missing_key.exit_code, kExitBadInput);
  EXPECT_NE(missing_key.err.find("image_height: missing"), std::string::npos) << missing_key.err;
  const auto both = test::safecell_cli(
      {"camera", "import", "--ros", (scratch.path() / "left.yaml").string(), "--mc-calib",
       (scratch.path() / "left.yaml").string(), "--pose", (scratch.path() / "pose.yaml").string(),
       "--out", (scratch.path() / "x.yaml").string()});
  EXPECT_EQ(both.exit_code, kExitBadInput);
  EXPECT_NE(both.err.find("exactly one of --ros FILE and --mc-calib FILE"), std::string::npos)
      << both.err;
  EXPECT_FALSE(fs::exists(scratch.path() / "x.yaml"));
}

}  // namespace
}  // namespace safecell
