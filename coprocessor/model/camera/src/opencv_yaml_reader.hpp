#pragma once
// OpenCV YAML files (as cv::FileStorage writes them) read with errors that name the file, the key,
// the value and what was expected: this project's calibration files, and MC-Calib's. They are
// parsed by yaml-cpp behind the YAML gate: OpenCV's own parser hangs on some malformed files.
// Private to the camera module.

#include <yaml-cpp/yaml.h>

#include <Eigen/Core>
#include <cmath>
#include <filesystem>
#include <initializer_list>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "safecell/camera/camera_error.hpp"
#include "safecell/camera/camera_intrinsics.hpp"

namespace safecell {

inline constexpr const char* kRotationKey = "cell_to_camera_rotation";
inline constexpr const char* kRvecKey = "cell_to_camera_rvec";
inline constexpr const char* kTranslationKey = "cell_to_camera_translation_m";
// Larger is no calibration matrix; keeps rows * cols sane.
inline constexpr int kMaxMatrixSide = 64;

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

// A node as an error message shows it: a number, a quoted text, "a list of N entries", "nothing".
std::string value_shown(const YAML::Node& node);

// A plain (unquoted) scalar read as OpenCV reads it: a whole number, or any number (".nan" and
// ".inf" included). A quoted "5" is a text to OpenCV, so it is none here.
std::optional<long long> whole_number_of(const YAML::Node& node);
std::optional<double> number_of(const YAML::Node& node);

// The file's tree: its text begins with "%YAML:1.0", holds one document, and passes the YAML gate.
// Throws CameraError naming the file and `expected` (what the file should have been).
YAML::Node opencv_yaml_tree(const std::filesystem::path& path, const std::string& expected);

// The keys of one mapping of such a file, read with errors that name the file, the key, the value
// and what was expected.
class CalibrationReader {
 public:
  CalibrationReader(std::string source, const YAML::Node& root);

  [[noreturn]] void fail(const std::string& key, const std::string& problem) const {
    throw_camera_error(source_, key, problem);
  }

  // Present with a value (an empty "key:" is as good as missing).
  bool has(const char* key) const;

  // A key outside `known` is refused: a misspelt key would otherwise be passed over.
  void refuse_unknown_keys(std::initializer_list<const char*> known) const;

  YAML::Node require(const char* key, const std::string& expected) const;

  int image_size(const char* key) const;

  // An opencv-matrix whose shape is one of `shapes` ({rows, cols}) and whose entries are finite.
  Matrix matrix(const char* key, std::initializer_list<std::pair<int, int>> shapes) const;

 private:
  int side(const char* key, const YAML::Node& node, const char* name) const;
  Matrix matrix_of(const char* key, const YAML::Node& node, const std::string& expected) const;

  std::string source_;
  YAML::Node root_;
};

// camera_matrix: [fx 0 cx; 0 fy cy; 0 0 1] (the model has no skew).
void read_camera_matrix(const CalibrationReader& reader, CameraIntrinsics& intrinsics);

// A 5x1, 1x5, 4x1 or 1x4 matrix of k1 k2 p1 p2 [k3] under `key`.
LensDistortion read_distortion(const CalibrationReader& reader, const char* key);

// The rotation (kRotationKey, or kRvecKey as a Rodrigues vector) and the key it came from.
std::pair<Eigen::Matrix3d, std::string> read_rotation(const CalibrationReader& reader);

}  // namespace safecell
