#include "opencv_yaml_reader.hpp"

#include <yaml-cpp/depthguard.h>
#include <yaml-cpp/yaml.h>

#include <cmath>
#include <fstream>
#include <map>
#include <opencv2/calib3d.hpp>
#include <sstream>
#include <tuple>
#include <utility>
#include <vector>

#include "error_text.hpp"
#include "safecell/camera/camera_error.hpp"

namespace safecell {

std::string shown(const cv::FileNode& node) {
  if (node.isInt()) return std::to_string(static_cast<int>(node));
  if (node.isReal()) return number_text(node.real());
  if (node.isString()) return "'" + node.string() + "'";
  if (node.isSeq()) return "a list of " + std::to_string(node.size()) + " entries";
  if (node.isMap()) return "a mapping";
  return "nothing";
}

namespace {

// Larger is no calibration: MC-Calib's file of a dozen cameras and boards is tens of kB.
constexpr std::uintmax_t kMaxCalibrationBytes = std::uintmax_t{4} << 20;
// Calibration files nest three deep (a file, a matrix, its data); OpenCV's own YAML parser
// recurses once per level and overflows its stack on files nested some 100,000 deep.
constexpr int kMaxCalibrationDepth = 16;

// The tree as yaml-cpp reads it (it refuses nesting beyond its own limit instead of recursing on),
// walked without recursion: nesting beyond kMaxCalibrationDepth, or a key given twice in any
// mapping (OpenCV would answer one of them), is refused before OpenCV's parser sees the text.
void check_yaml_structure(const std::string& source, const std::string& text,
                          const std::string& expected) {
  YAML::Node root;
  try {
    root = YAML::Load(text);
  } catch (const YAML::DeepRecursion& error) {
    throw_camera_error(source, "(file)",
                       "nested deeper than " + std::to_string(kMaxCalibrationDepth) +
                           " levels (line " + std::to_string(error.mark.line + 1) + "), expected " +
                           expected);
  } catch (const YAML::Exception& error) {
    throw_camera_error(source, "(file)",
                       "not valid YAML (line " + std::to_string(error.mark.line + 1) + ": " +
                           error.msg + "), expected " + expected);
  }
  std::vector<std::pair<YAML::Node, int>> open{{root, 1}};
  while (!open.empty()) {
    const auto [node, depth] = open.back();
    open.pop_back();
    if (depth > kMaxCalibrationDepth) {
      throw_camera_error(source, "(file)",
                         "nested deeper than " + std::to_string(kMaxCalibrationDepth) +
                             " levels (line " + std::to_string(node.Mark().line + 1) +
                             "), expected " + expected);
    }
    std::map<std::string, int> lines;
    for (const auto& entry : node) {
      if (node.IsMap()) {
        const std::string key = entry.first.IsScalar() ? entry.first.Scalar() : "";
        const int line = entry.first.Mark().line + 1;
        if (key.empty()) {
          throw_camera_error(
              source, "(file)",
              "a key with no name on line " + std::to_string(line) + ", expected " + expected);
        }
        if (const auto [first, added] = lines.emplace(key, line); !added) {
          throw_camera_error(source, key,
                             "given twice (lines " + std::to_string(first->second) + " and " +
                                 std::to_string(line) + "), expected once");
        }
        open.emplace_back(entry.second, depth + 1);
      } else {
        open.emplace_back(entry, depth + 1);
      }
    }
  }
}

}  // namespace

std::string opencv_yaml_text(const std::filesystem::path& path, const std::string& expected) {
  const std::string source = path.string();
  std::error_code error;
  if (!std::filesystem::exists(path, error)) {
    throw_camera_error(source, "(file)", "does not exist, expected " + expected);
  }
  if (std::filesystem::is_directory(path, error)) {
    throw_camera_error(source, "(file)", "is a directory, expected " + expected);
  }
  if (const auto bytes = std::filesystem::file_size(path, error);
      !error && bytes > kMaxCalibrationBytes) {
    throw_camera_error(source, "(file)",
                       std::to_string(bytes) + " bytes, expected at most " +
                           std::to_string(kMaxCalibrationBytes) + " for " + expected);
  }
  std::ifstream file(path, std::ios::binary);
  std::ostringstream text;
  if (file) text << file.rdbuf();
  if (!file || file.bad()) throw_camera_error(source, "(file)", "cannot be read");
  if (text.str().rfind("%YAML", 0) != 0) {
    throw_camera_error(source, "(file)", "does not begin with \"%YAML:1.0\", expected " + expected);
  }
  check_yaml_structure(source, text.str(), expected);
  return text.str();
}

cv::FileStorage open_opencv_yaml(const std::string& source, const std::string& yaml,
                                 const std::string& expected) {
  try {
    cv::FileStorage storage(
        yaml, cv::FileStorage::READ | cv::FileStorage::MEMORY | cv::FileStorage::FORMAT_YAML);
    if (storage.isOpened()) return storage;
  } catch (const std::exception& error) {
    throw_camera_error(
        source, "(file)",
        "not valid YAML (OpenCV: " + one_line(error.what()) + "), expected " + expected);
  }
  throw_camera_error(source, "(file)", "cannot be parsed, expected " + expected);
}

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

LensDistortion read_distortion(const CalibrationReader& reader, const char* key) {
  const Matrix d = reader.matrix(key, {{5, 1}, {1, 5}, {4, 1}, {1, 4}});
  return {d.values[0], d.values[1], d.values[2], d.values[3],
          d.values.size() == 5 ? d.values[4] : 0.0};
}

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

}  // namespace safecell
