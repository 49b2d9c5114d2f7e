#pragma once
// OpenCV YAML files (cv::FileStorage) read with errors that name the file, the key, the value and
// what was expected: this project's calibration files, and MC-Calib's, which OpenCV writes.
// Private to the camera module.

#include <Eigen/Core>
#include <cmath>
#include <filesystem>
#include <initializer_list>
#include <opencv2/core.hpp>
#include <string>
#include <utility>
#include <vector>

#include "error_text.hpp"
#include "safecell/camera/camera_error.hpp"
#include "safecell/camera/camera_intrinsics.hpp"

namespace safecell {

inline constexpr const char* kRotationKey = "cell_to_camera_rotation";
inline constexpr const char* kRvecKey = "cell_to_camera_rvec";
inline constexpr const char* kTranslationKey = "cell_to_camera_translation_m";
inline constexpr int kMaxMatrixSide =
    64;  // larger is no calibration matrix; keeps rows * cols sane

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

// A node as an error message shows it: a number, a quoted string, "a list of N entries".
std::string shown(const cv::FileNode& node);

// The file's text, checked to begin as OpenCV's YAML files must, with "%YAML:1.0". Throws
// CameraError naming the file and `expected` (what the file should have been).
std::string opencv_yaml_text(const std::filesystem::path& path, const std::string& expected);

// OpenCV's reader over that text. Throws CameraError when it cannot parse it, whatever OpenCV
// throws (its parser lets std::length_error out on some malformed keys, not only cv::Exception).
cv::FileStorage open_opencv_yaml(const std::string& source, const std::string& yaml,
                                 const std::string& expected);

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

  // A key outside `known` is refused: a misspelt key would otherwise be passed over.
  void refuse_unknown_keys(std::initializer_list<const char*> known) const {
    for (const std::string& key : root_.keys()) {
      bool found = false;
      std::string expected;
      for (const char* name : known) {
        found = found || key == name;
        expected += (expected.empty() ? "" : ", ") + std::string(name);
      }
      if (!found) fail(key, "unknown key, expected one of " + expected);
    }
  }

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

// camera_matrix: [fx 0 cx; 0 fy cy; 0 0 1] (the model has no skew).
void read_camera_matrix(const CalibrationReader& reader, CameraIntrinsics& intrinsics);

// A 5x1, 1x5, 4x1 or 1x4 matrix of k1 k2 p1 p2 [k3] under `key`.
LensDistortion read_distortion(const CalibrationReader& reader, const char* key);

// The rotation (kRotationKey, or kRvecKey as a Rodrigues vector) and the key it came from.
std::pair<Eigen::Matrix3d, std::string> read_rotation(const CalibrationReader& reader);

}  // namespace safecell
