#include "safecell/camera/calibration_file.hpp"

#include <gtest/gtest.h>
#include <unistd.h>

#include <Eigen/Geometry>
#include <filesystem>
#include <fstream>
#include <opencv2/core/persistence.hpp>
#include <string>
#include <utility>
#include <vector>

#include "random_camera.hpp"
#include "safecell/camera/camera_error.hpp"
#include "safecell/test/property.hpp"
#include "safecell/test/scratch_folder.hpp"

namespace safecell {
namespace {

namespace fs = std::filesystem;

std::string matrix(int rows, int cols, const std::string& data) {
  return "!!opencv-matrix\n   rows: " + std::to_string(rows) +
         "\n   cols: " + std::to_string(cols) + "\n   dt: d\n   data: [ " + data + " ]";
}

using Entries = std::vector<std::pair<std::string, std::string>>;

// A valid calibration: 640 x 480 px, fx 500, fy 400, a quarter turn about z, t = (1, 2, 3) m.
Entries good_entries() {
  return {
      {"image_width", "640"},
      {"image_height", "480"},
      {"camera_matrix", matrix(3, 3, "500., 0., 320., 0., 400., 240., 0., 0., 1.")},
      {"distortion_coefficients", matrix(5, 1, "-0.1, 0.01, 0.001, -0.002, 0.003")},
      {"cell_to_camera_rotation", matrix(3, 3, "0., 1., 0., -1., 0., 0., 0., 0., 1.")},
      {"cell_to_camera_translation_m", matrix(3, 1, "1., 2., 3.")},
  };
}

std::string yaml_of(const Entries& entries) {
  std::string text = "%YAML:1.0\n---\n";
  for (const auto& [key, value] : entries) text.append(key).append(": ").append(value).append("\n");
  return text;
}

Entries with(Entries entries, const std::string& key, const std::string& value) {
  for (auto& entry : entries) {
    if (entry.first == key) {
      entry.second = value;
      return entries;
    }
  }
  entries.emplace_back(key, value);
  return entries;
}

Entries without(Entries entries, const std::string& key) {
  std::erase_if(entries, [&](const auto& entry) { return entry.first == key; });
  return entries;
}

fs::path write_text(const fs::path& path, const std::string& text) {
  std::ofstream(path, std::ios::binary) << text;
  return path;
}

std::string read_error_of(const fs::path& path) {
  try {
    static_cast<void>(read_camera_calibration(path, "cam"));
  } catch (const CameraError& error) {
    return error.what();
  }
  return "(no error)";
}

TEST(CalibrationFile, ReadsEveryKey) {
  const test::ScratchFolder dir;
  const PinholeCamera camera =
      read_camera_calibration(write_text(dir.path() / "good.yaml", yaml_of(good_entries())), "c1");
  EXPECT_EQ(camera.name(), "c1");
  const CameraIntrinsics& in = camera.intrinsics();
  EXPECT_EQ(in.width_px, 640);
  EXPECT_EQ(in.height_px, 480);
  EXPECT_EQ(in.fx_px, 500.0);
  EXPECT_EQ(in.fy_px, 400.0);
  EXPECT_EQ(in.cx_px, 320.0);
  EXPECT_EQ(in.cy_px, 240.0);
  EXPECT_EQ(in.distortion, (LensDistortion{-0.1, 0.01, 0.001, -0.002, 0.003}));
  Eigen::Matrix3d rotation;
  rotation << 0, 1, 0, -1, 0, 0, 0, 0, 1;
  EXPECT_EQ(camera.cell_to_camera().linear(), rotation);
  EXPECT_EQ(camera.cell_to_camera().translation(), Eigen::Vector3d(1, 2, 3));
  EXPECT_TRUE(camera.position_m().isApprox(Eigen::Vector3d(2, -1, -3), 1e-15));
}

TEST(CalibrationFile, AcceptsTheOtherSpellings) {
  const test::ScratchFolder dir;
  // A Rodrigues vector for the rotation: a quarter turn about z.
  Entries entries = without(good_entries(), "cell_to_camera_rotation");
  entries.emplace_back("cell_to_camera_rvec", matrix(1, 3, "0., 0., 1.5707963267948966"));
  // Four distortion coefficients in a row (k3 = 0), and extra keys.
  entries = with(entries, "distortion_coefficients", matrix(1, 4, "-0.1, 0.01, 0.001, -0.002"));
  entries.emplace_back("avg_reprojection_error", "0.21");
  const PinholeCamera camera =
      read_camera_calibration(write_text(dir.path() / "other.yaml", yaml_of(entries)), "c2");
  const Eigen::Matrix3d expected =
      Eigen::AngleAxisd(1.5707963267948966, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  EXPECT_LT((camera.cell_to_camera().linear() - expected).norm(), 1e-15);
  EXPECT_EQ(camera.intrinsics().distortion, (LensDistortion{-0.1, 0.01, 0.001, -0.002, 0.0}));
}

TEST(CalibrationFile, WriteThenReadGivesTheSameCamera) {
  const test::ScratchFolder dir;
  const fs::path path = dir.path() / "cam.yaml";
  test::PropertyRun run(100);
  for (int i = 0; i < run.iterations(); ++i) {
    const PinholeCamera camera = test::random_camera(run.rng(), true, "written");
    write_camera_calibration(path, camera);
    const PinholeCamera read = read_camera_calibration(path, "read");
    EXPECT_EQ(read.name(), "read");
    const CameraIntrinsics& a = camera.intrinsics();
    const CameraIntrinsics& b = read.intrinsics();
    EXPECT_EQ(a.width_px, b.width_px);
    EXPECT_EQ(a.height_px, b.height_px);
    const Eigen::VectorXd values_a =
        (Eigen::VectorXd(9) << a.fx_px, a.fy_px, a.cx_px, a.cy_px, a.distortion.k1, a.distortion.k2,
         a.distortion.p1, a.distortion.p2, a.distortion.k3)
            .finished();
    const Eigen::VectorXd values_b =
        (Eigen::VectorXd(9) << b.fx_px, b.fy_px, b.cx_px, b.cy_px, b.distortion.k1, b.distortion.k2,
         b.distortion.p1, b.distortion.p2, b.distortion.k3)
            .finished();
    ASSERT_LE((values_a - values_b).cwiseAbs().maxCoeff(), 1e-12 * values_a.cwiseAbs().maxCoeff())
        << "iteration " << i;
    ASSERT_LE(
        (camera.cell_to_camera().matrix() - read.cell_to_camera().matrix()).cwiseAbs().maxCoeff(),
        1e-12)
        << "iteration " << i;
  }
  // Nothing is left beside the file: the temporary files were renamed over it.
  std::vector<fs::path> files;
  for (const auto& entry : fs::directory_iterator(dir.path())) files.push_back(entry.path());
  EXPECT_EQ(files, std::vector<fs::path>{path});
}

TEST(CalibrationFile, OpenCvReadsWhatWeWrite) {
  const test::ScratchFolder dir;
  const fs::path path = dir.path() / "cam.yaml";
  CameraIntrinsics intrinsics;
  intrinsics = {500.0, 400.0, 320.0, 240.0, {-0.1, 0.01, 0.001, -0.002, 0.003}, 640, 480};
  write_camera_calibration(path, PinholeCamera("c", intrinsics, Eigen::Isometry3d::Identity()));
  const cv::FileStorage storage(path.string(), cv::FileStorage::READ);
  ASSERT_TRUE(storage.isOpened());
  EXPECT_EQ(static_cast<int>(storage["image_width"]), 640);
  cv::Mat k;
  cv::Mat distortion;
  storage["camera_matrix"] >> k;
  storage["distortion_coefficients"] >> distortion;
  ASSERT_EQ(k.rows, 3);
  ASSERT_EQ(k.cols, 3);
  EXPECT_EQ(k.at<double>(0, 0), 500.0);
  EXPECT_EQ(k.at<double>(1, 2), 240.0);
  EXPECT_EQ(k.at<double>(2, 2), 1.0);
  ASSERT_EQ(distortion.total(), 5u);
  EXPECT_EQ(distortion.at<double>(4), 0.003);
}

TEST(CalibrationFile, WritingWhereNoFileCanBeIsAnError) {
  const test::ScratchFolder dir;
  const PinholeCamera camera =
      PinholeCamera::look_at("c", {0, 0, 3}, {0, 0, 0}, Eigen::Vector3d::UnitY(), 1.0, 64, 48);
  const fs::path nowhere = dir.path() / "missing" / "cam.yaml";
  try {
    write_camera_calibration(nowhere, camera);
    FAIL() << "no error";
  } catch (const CameraError& error) {
    EXPECT_EQ(std::string(error.what()).rfind(nowhere.string() + ": (file): cannot create", 0), 0u)
        << error.what();
  }
  // A directory in the way: the rename fails and the temporary file is cleaned up.
  fs::create_directories(dir.path() / "taken.yaml" / "inside");
  EXPECT_THROW(write_camera_calibration(dir.path() / "taken.yaml", camera), CameraError);
  std::size_t entries = 0;
  for ([[maybe_unused]] const auto& entry : fs::directory_iterator(dir.path())) ++entries;
  EXPECT_EQ(entries, 1u);
}

struct BadCase {
  const char* what;
  std::string text;
  std::string key;       // the key the message must name
  std::string fragment;  // and what it must say about it
};

std::vector<BadCase> bad_cases() {
  const Entries good = good_entries();
  const auto m3 = [](const std::string& data) { return matrix(3, 3, data); };
  return {
      {"not YAML", "%YAML:1.0\n---\n{{{{ not yaml ]]]\n", "(file)", "not valid YAML (line 3"},
      {"no %YAML line", yaml_of(good).substr(10), "(file)",
       "does not begin with \"%YAML:1.0\", expected an OpenCV YAML calibration"},
      {"binary",
       std::string("\x7f"
                   "ELF\x02\x01\x01\0\0\x03\xff\xfe",
                   12),
       "(file)", "does not begin with"},
      {"empty", "", "(file)", "does not begin with"},
      {"a second directive (OpenCV hangs on it)", "%YAML:1.0\n---%YAML:1.0\n-\n-im-\niza", "(file)",
       "a YAML directive or document marker on line 2 ('---%YAML:1.0')"},
      {"a second document", yaml_of(good) + "---\nimage_width: 1\n", "(file)",
       "document marker on line"},
      {"a directive further down", yaml_of(good) + "%TAG ! x\n", "(file)",
       "a YAML directive or document marker on line"},
      {"only the header", "%YAML:1.0\n", "(file)",
       "expected a mapping of calibration keys, got nothing"},
      {"a list", "%YAML:1.0\n---\n- 1\n- 2\n", "(file)",
       "expected a mapping of calibration keys, got a list"},
      {"no image_width", yaml_of(without(good, "image_width")), "image_width",
       "missing, expected a whole number of pixels > 0"},
      {"zero width", yaml_of(with(good, "image_width", "0")), "image_width", "0, expected"},
      {"negative height", yaml_of(with(good, "image_height", "-480")), "image_height",
       "-480, expected"},
      {"fractional width", yaml_of(with(good, "image_width", "640.5")), "image_width",
       "640.5, expected"},
      {"text width", yaml_of(with(good, "image_width", "wide")), "image_width", "'wide', expected"},
      {"no camera_matrix", yaml_of(without(good, "camera_matrix")), "camera_matrix",
       "missing, expected a 3x3 opencv-matrix"},
      {"2x3 camera_matrix",
       yaml_of(with(good, "camera_matrix", matrix(2, 3, "500., 0., 320., 0., 400., 240."))),
       "camera_matrix", "a 2x3 matrix, expected a 3x3 opencv-matrix"},
      {"camera_matrix as a list",
       yaml_of(with(good, "camera_matrix", "[ 500., 0., 320., 0., 400., 240., 0., 0., 1. ]")),
       "camera_matrix", "a list of 9 entries, expected a 3x3 opencv-matrix"},
      {"short data", yaml_of(with(good, "camera_matrix", m3("500., 0., 320., 0., 400., 240."))),
       "camera_matrix", "data is a list of 6 entries, expected a list of 9 numbers"},
      {"no rows",
       yaml_of(with(good, "camera_matrix", "!!opencv-matrix\n   cols: 3\n   data: [ 1. ]")),
       "camera_matrix", "rows is nothing, expected a whole number"},
      {"NaN in camera_matrix",
       yaml_of(with(good, "camera_matrix", m3("500., 0., .NaN, 0., 400., 240., 0., 0., 1."))),
       "camera_matrix", "entry (0, 2) is nan, expected a finite number"},
      {"text in camera_matrix",
       yaml_of(with(good, "camera_matrix", m3("fx, 0., 320., 0., 400., 240., 0., 0., 1."))),
       "camera_matrix", "entry (0, 0) is 'fx', expected a number"},
      {"skew",
       yaml_of(with(good, "camera_matrix", m3("500., 0.5, 320., 0., 400., 240., 0., 0., 1."))),
       "camera_matrix", "entry (0, 1) is 0.5, expected 0"},
      {"bottom row",
       yaml_of(with(good, "camera_matrix", m3("500., 0., 320., 0., 400., 240., 0., 0., 2."))),
       "camera_matrix", "entry (2, 2) is 2, expected 1"},
      {"negative fx",
       yaml_of(with(good, "camera_matrix", m3("-500., 0., 320., 0., 400., 240., 0., 0., 1."))),
       "camera_matrix (fx)", "-500, expected a finite focal length in pixels > 0"},
      {"no distortion", yaml_of(without(good, "distortion_coefficients")),
       "distortion_coefficients", "missing, expected a 5x1 or 1x5 or 4x1 or 1x4 opencv-matrix"},
      {"3 coefficients",
       yaml_of(with(good, "distortion_coefficients", matrix(3, 1, "0.1, 0.01, 0.001"))),
       "distortion_coefficients", "a 3x1 matrix, expected a 5x1 or 1x5 or 4x1 or 1x4"},
      {"8 coefficients",
       yaml_of(with(good, "distortion_coefficients", matrix(1, 8, "0, 0, 0, 0, 0, 0, 0, 0"))),
       "distortion_coefficients", "a 1x8 matrix, expected"},
      {"infinite coefficient",
       yaml_of(with(good, "distortion_coefficients", matrix(5, 1, "0.1, .Inf, 0., 0., 0."))),
       "distortion_coefficients", "entry (1, 0) is inf, expected a finite number"},
      {"folding lens",
       yaml_of(with(good, "distortion_coefficients", matrix(5, 1, "-0.9, 0., 0., 0., 0."))),
       "distortion_coefficients", "[-0.9, 0, 0, 0, 0] fold the image over"},
      {"stretched rotation",
       yaml_of(with(good, "cell_to_camera_rotation", m3("0., 1.1, 0., -1., 0., 0., 0., 0., 1."))),
       "cell_to_camera_rotation", "[[0, 1.1, 0], [-1, 0, 0], [0, 0, 1]] is not a rotation"},
      {"mirror",
       yaml_of(with(good, "cell_to_camera_rotation", m3("0., 1., 0., 1., 0., 0., 0., 0., 1."))),
       "cell_to_camera_rotation", "det = -1), expected an orthonormal matrix with determinant +1"},
      {"NaN rotation",
       yaml_of(with(good, "cell_to_camera_rotation", m3("0., 1., 0., -1., .nan, 0., 0., 0., 1."))),
       "cell_to_camera_rotation", "entry (1, 1) is nan"},
      {"no rotation", yaml_of(without(good, "cell_to_camera_rotation")), "cell_to_camera_rotation",
       "missing, expected a 3x3 rotation matrix (or cell_to_camera_rvec"},
      {"both rotations", yaml_of(with(good, "cell_to_camera_rvec", matrix(3, 1, "0., 0., 1."))),
       "cell_to_camera_rotation", "given together with cell_to_camera_rvec"},
      {"2x1 rvec",
       yaml_of(with(without(good, "cell_to_camera_rotation"), "cell_to_camera_rvec",
                    matrix(2, 1, "0., 1."))),
       "cell_to_camera_rvec", "a 2x1 matrix, expected a 3x1 or 1x3 opencv-matrix"},
      {"NaN rvec",
       yaml_of(with(without(good, "cell_to_camera_rotation"), "cell_to_camera_rvec",
                    matrix(3, 1, "0., .NaN, 1."))),
       "cell_to_camera_rvec", "entry (1, 0) is nan"},
      {"no translation", yaml_of(without(good, "cell_to_camera_translation_m")),
       "cell_to_camera_translation_m", "missing, expected a 3x1 or 1x3 opencv-matrix"},
      {"3x3 translation",
       yaml_of(with(good, "cell_to_camera_translation_m", m3("1,2,3,4,5,6,7,8,9"))),
       "cell_to_camera_translation_m", "a 3x3 matrix, expected a 3x1 or 1x3"},
      {"infinite translation",
       yaml_of(with(good, "cell_to_camera_translation_m", matrix(3, 1, "1., -.Inf, 3."))),
       "cell_to_camera_translation_m", "entry (1, 0) is -inf, expected a finite number"},
      {"a key twice", yaml_of(good) + "image_width: 6400\n", "image_width",
       "given twice (lines 3 and "},
      {"a key in a matrix twice",
       yaml_of(with(good, "camera_matrix", matrix(3, 3, "1") + "\n   rows: 1")), "rows",
       "given twice"},
      {"unknown key", yaml_of(with(good, "image_widht", "704")), "image_widht",
       "unknown key, expected one of image_width"},
      {"fisheye", yaml_of(with(good, "fisheye_model", "1")), "fisheye_model", "unknown key"},
      {"nested 100,000 deep",
       "%YAML:1.0\n---\nimage_width: " + std::string(100000, '[') + std::string(100000, ']') + "\n",
       "(file)", "nested deeper than 16 levels"},
      {"nested 17 deep",
       "%YAML:1.0\n---\nimage_width: " + std::string(17, '[') + std::string(17, ']') + "\n",
       "(file)", "nested deeper than 16 levels"},
      {"distortion of 2e9",
       yaml_of(with(good, "distortion_coefficients", matrix(5, 1, "2e9, 0., 0., 0., 0."))),
       "distortion_coefficients", "2e+09, expected a value within +-1000 (a radial term k)"},
      {"camera 1e308 away",
       yaml_of(with(good, "cell_to_camera_translation_m", matrix(3, 1, "1e308, 0., 0."))),
       "cell_to_camera_translation_m", "1e+308, expected a value within +-1e+06"},
  };
}

TEST(CalibrationFile, EveryMalformedFileIsNamedWithItsKey) {
  const test::ScratchFolder dir;
  int n = 0;
  for (const BadCase& bad : bad_cases()) {
    const fs::path path =
        write_text(dir.path() / ("bad" + std::to_string(n++) + ".yaml"), bad.text);
    const std::string message = read_error_of(path);
    const std::string head = path.string() + ": " + bad.key + ": ";
    EXPECT_EQ(message.rfind(head, 0), 0u) << bad.what << ": " << message;
    EXPECT_NE(message.find(bad.fragment, head.size()), std::string::npos)
        << bad.what << ": " << message;
    EXPECT_NE(message.find("expected"), std::string::npos) << bad.what << ": " << message;
    EXPECT_EQ(message.find('\n'), std::string::npos) << bad.what << ": " << message;
  }
}

TEST(CalibrationFile, FilesThatCannotBeReadAreNamed) {
  const test::ScratchFolder dir;
  const fs::path missing = dir.path() / "missing.yaml";
  EXPECT_EQ(read_error_of(missing),
            missing.string() + ": (file): does not exist, expected an OpenCV YAML calibration");
  EXPECT_EQ(read_error_of(dir.path()),
            dir.path().string() + ": (file): is a directory, expected an OpenCV YAML calibration");
}

}  // namespace
}  // namespace safecell
