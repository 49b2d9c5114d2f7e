#include "opencv_yaml_reader.hpp"

#include <cmath>
#include <opencv2/calib3d.hpp>
#include <tuple>
#include <utility>
#include <vector>

#include "error_text.hpp"
#include "safecell/camera/camera_error.hpp"
#include "yaml_gate.hpp"

namespace safecell {

std::string shown(const cv::FileNode& node) {
  if (node.isInt()) return std::to_string(static_cast<int>(node));
  if (node.isReal()) return number_text(node.real());
  if (node.isString()) return "'" + node.string() + "'";
  if (node.isSeq()) return "a list of " + std::to_string(node.size()) + " entries";
  if (node.isMap()) return "a mapping";
  return "nothing";
}

std::string opencv_yaml_text(const std::filesystem::path& path, const std::string& expected) {
  const std::string source = path.string();
  std::string text = yaml_file_text(path, expected);
  if (text.rfind("%YAML", 0) != 0) {
    throw_camera_error(source, "(file)", "does not begin with \"%YAML:1.0\", expected " + expected);
  }
  static_cast<void>(checked_yaml_tree(source, text, expected));
  return text;
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
