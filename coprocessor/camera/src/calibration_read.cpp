#include <Eigen/Geometry>
#include <cmath>
#include <fstream>
#include <initializer_list>
#include <opencv2/calib3d.hpp>
#include <opencv2/core.hpp>
#include <sstream>
#include <tuple>
#include <utility>
#include <vector>

#include "camera_checks.hpp"
#include "error_text.hpp"
#include "safecell/camera/calibration_file.hpp"
#include "safecell/camera/camera_error.hpp"

namespace safecell {
namespace {

constexpr const char* kRotationKey = "cell_to_camera_rotation";
constexpr const char* kRvecKey = "cell_to_camera_rvec";
constexpr int kMaxMatrixSide = 64;  // larger is no calibration matrix; keeps rows * cols sane

// An opencv-matrix node, entries row by row.
struct Matrix {
  int rows = 0;
  int cols = 0;
  std::vector<double> values;

  double at(int row, int col) const {
    return values[static_cast<std::size_t>(row) * static_cast<std::size_t>(cols) +
                  static_cast<std::size_t>(col)];
  }
  std::string shape() const { return std::to_string(rows) + "x" + std::to_string(cols); }
};

std::string shown(const cv::FileNode& node) {
  if (node.isInt()) return std::to_string(static_cast<int>(node));
  if (node.isReal()) return number_text(node.real());
  if (node.isString()) return "'" + node.string() + "'";
  if (node.isSeq()) return "a list of " + std::to_string(node.size()) + " entries";
  if (node.isMap()) return "a mapping";
  return "nothing";
}

// The file's text, checked to begin as OpenCV's YAML files must, with "%YAML:1.0".
std::string yaml_text_of(const std::filesystem::path& path) {
  const std::string source = path.string();
  std::error_code error;
  if (!std::filesystem::exists(path, error)) {
    throw_camera_error(source, "(file)", "does not exist, expected an OpenCV YAML calibration");
  }
  if (std::filesystem::is_directory(path, error)) {
    throw_camera_error(source, "(file)", "is a directory, expected an OpenCV YAML calibration");
  }
  std::ifstream file(path, std::ios::binary);
  std::ostringstream text;
  if (file) text << file.rdbuf();
  if (!file || file.bad()) throw_camera_error(source, "(file)", "cannot be read");
  if (text.str().rfind("%YAML", 0) != 0) {
    throw_camera_error(source, "(file)",
                       "does not begin with \"%YAML:1.0\", expected an OpenCV YAML calibration");
  }
  return text.str();
}

class CalibrationReader {
 public:
  CalibrationReader(std::string source, const cv::FileNode& root)
      : source_(std::move(source)), root_(root) {
    if (!root_.isMap()) {
      fail("(file)", "expected a mapping of calibration keys, got " + shown(root_));
    }
  }

  [[noreturn]] void fail(const std::string& key, const std::string& problem) const {
    throw_camera_error(source_, key, problem);
  }

  bool has(const char* key) const { return !root_[key].isNone(); }

  cv::FileNode require(const char* key, const std::string& expected) const {
    const cv::FileNode node = root_[key];
    if (node.isNone()) fail(key, "missing, expected " + expected);
    return node;
  }

  int image_size(const char* key) const {
    const std::string expected = "a whole number of pixels > 0";
    const cv::FileNode node = require(key, expected);
    if (!node.isInt() || static_cast<int>(node) <= 0) {
      fail(key, shown(node) + ", expected " + expected);
    }
    return static_cast<int>(node);
  }

  // An opencv-matrix whose shape is one of `shapes` ({rows, cols}) and whose entries are finite.
  Matrix matrix(const char* key, std::initializer_list<std::pair<int, int>> shapes) const {
    std::string expected;
    for (const auto& [rows, cols] : shapes) {
      expected +=
          (expected.empty() ? "a " : " or ") + std::to_string(rows) + "x" + std::to_string(cols);
    }
    expected += " opencv-matrix (rows, cols, dt, data)";
    Matrix m = matrix_of(key, require(key, expected), expected);
    bool allowed = false;
    for (const auto& [rows, cols] : shapes) allowed = allowed || (m.rows == rows && m.cols == cols);
    if (!allowed) fail(key, "a " + m.shape() + " matrix, expected " + expected);
    return m;
  }

 private:
  int side(const char* key, const cv::FileNode& node, const char* name) const {
    const cv::FileNode value = node[name];
    if (!value.isInt() || static_cast<int>(value) <= 0 ||
        static_cast<int>(value) > kMaxMatrixSide) {
      fail(key, std::string(name) + " is " + shown(value) + ", expected a whole number in 1.." +
                    std::to_string(kMaxMatrixSide));
    }
    return static_cast<int>(value);
  }

  Matrix matrix_of(const char* key, const cv::FileNode& node, const std::string& expected) const {
    if (!node.isMap()) fail(key, shown(node) + ", expected " + expected);
    Matrix m;
    m.rows = side(key, node, "rows");
    m.cols = side(key, node, "cols");
    const cv::FileNode data = node["data"];
    const auto count = static_cast<std::size_t>(m.rows) * static_cast<std::size_t>(m.cols);
    if (!data.isSeq() || data.size() != count) {
      fail(key, "data is " + shown(data) + ", expected a list of " + std::to_string(count) +
                    " numbers for a " + m.shape() + " matrix");
    }
    for (std::size_t i = 0; i < count; ++i) {
      const cv::FileNode entry = data[static_cast<int>(i)];
      const std::string at = "entry (" + std::to_string(i / static_cast<std::size_t>(m.cols)) +
                             ", " + std::to_string(i % static_cast<std::size_t>(m.cols)) + ")";
      if (!entry.isInt() && !entry.isReal()) {
        fail(key, at + " is " + shown(entry) + ", expected a number");
      }
      const double value = entry.real();
      if (!std::isfinite(value)) {
        fail(key, at + " is " + number_text(value) + ", expected a finite number");
      }
      m.values.push_back(value);
    }
    return m;
  }

  std::string source_;
  cv::FileNode root_;
};

// [fx 0 cx; 0 fy cy; 0 0 1]: the model has no skew.
void read_camera_matrix(const CalibrationReader& reader, CameraIntrinsics& intrinsics) {
  const char* key = "camera_matrix";
  const Matrix k = reader.matrix(key, {{3, 3}});
  for (const auto& [row, col, value] :
       {std::tuple{0, 1, 0.0}, std::tuple{1, 0, 0.0}, std::tuple{2, 0, 0.0}, std::tuple{2, 1, 0.0},
        std::tuple{2, 2, 1.0}}) {
    if (k.at(row, col) != value) {
      reader.fail(key, "entry (" + std::to_string(row) + ", " + std::to_string(col) + ") is " +
                           number_text(k.at(row, col)) + ", expected " + number_text(value) +
                           " as in [fx 0 cx; 0 fy cy; 0 0 1]");
    }
  }
  intrinsics.fx_px = k.at(0, 0);
  intrinsics.fy_px = k.at(1, 1);
  intrinsics.cx_px = k.at(0, 2);
  intrinsics.cy_px = k.at(1, 2);
}

LensDistortion read_distortion(const CalibrationReader& reader) {
  const Matrix d = reader.matrix("distortion_coefficients", {{5, 1}, {1, 5}, {4, 1}, {1, 4}});
  return {d.values[0], d.values[1], d.values[2], d.values[3],
          d.values.size() == 5 ? d.values[4] : 0.0};
}

// The rotation and the key it came from.
std::pair<Eigen::Matrix3d, std::string> read_rotation(const CalibrationReader& reader) {
  const bool has_matrix = reader.has(kRotationKey);
  const bool has_rvec = reader.has(kRvecKey);
  if (has_matrix && has_rvec) {
    reader.fail(kRotationKey,
                std::string("given together with ") + kRvecKey + ", expected exactly one of them");
  }
  Eigen::Matrix3d rotation;
  if (has_rvec) {
    const Matrix rvec = reader.matrix(kRvecKey, {{3, 1}, {1, 3}});
    cv::Mat matrix;
    cv::Rodrigues(cv::Mat(rvec.values, true), matrix);
    for (int r = 0; r < 3; ++r) {
      for (int c = 0; c < 3; ++c) rotation(r, c) = matrix.at<double>(r, c);
    }
    return {rotation, kRvecKey};
  }
  if (!has_matrix) {
    reader.fail(kRotationKey, std::string("missing, expected a 3x3 rotation matrix (or ") +
                                  kRvecKey + ", a 3x1 Rodrigues vector)");
  }
  const Matrix m = reader.matrix(kRotationKey, {{3, 3}});
  for (int r = 0; r < 3; ++r) {
    for (int c = 0; c < 3; ++c) rotation(r, c) = m.at(r, c);
  }
  return {rotation, kRotationKey};
}

PinholeCamera read_camera(const CalibrationReader& reader, const std::string& source,
                          std::string name) {
  CameraIntrinsics intrinsics;
  intrinsics.width_px = reader.image_size("image_width");
  intrinsics.height_px = reader.image_size("image_height");
  read_camera_matrix(reader, intrinsics);
  intrinsics.distortion = read_distortion(reader);
  const auto [rotation, rotation_key] = read_rotation(reader);
  const char* translation_key = "cell_to_camera_translation_m";
  const Matrix t = reader.matrix(translation_key, {{3, 1}, {1, 3}});

  Eigen::Isometry3d cell_to_camera = Eigen::Isometry3d::Identity();
  cell_to_camera.linear() = rotation;
  cell_to_camera.translation() = Eigen::Vector3d(t.values[0], t.values[1], t.values[2]);
  // The same checks as the camera's own, so the message names this file and its keys.
  check_camera_values(source,
                      {"image_width", "image_height", "camera_matrix (fx)", "camera_matrix (fy)",
                       "camera_matrix (cx)", "camera_matrix (cy)", "distortion_coefficients",
                       rotation_key, translation_key},
                      intrinsics, rotation, cell_to_camera.translation());
  return {std::move(name), intrinsics, cell_to_camera};
}

}  // namespace

PinholeCamera read_camera_calibration(const std::filesystem::path& path, std::string name) {
  const std::string source = path.string();
  const std::string yaml = yaml_text_of(path);
  try {
    const cv::FileStorage storage(
        yaml, cv::FileStorage::READ | cv::FileStorage::MEMORY | cv::FileStorage::FORMAT_YAML);
    if (!storage.isOpened()) {
      throw_camera_error(source, "(file)", "cannot be parsed, expected an OpenCV YAML calibration");
    }
    return read_camera(CalibrationReader(source, storage.root()), source, std::move(name));
  } catch (const cv::Exception& error) {
    throw_camera_error(
        source, "(file)",
        "not valid YAML (" + one_line(error.what()) + "), expected an OpenCV YAML calibration");
  }
}

}  // namespace safecell
