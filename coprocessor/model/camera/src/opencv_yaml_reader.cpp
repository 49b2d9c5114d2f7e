#include "opencv_yaml_reader.hpp"

#include <cmath>
#include <limits>
#include <opencv2/calib3d.hpp>
#include <string_view>
#include <tuple>
#include <utility>
#include <vector>

#include "error_text.hpp"
#include "safecell/camera/camera_error.hpp"
#include "yaml_gate.hpp"

namespace safecell {

std::optional<long long> whole_number_of(const YAML::Node& node) {
  long long value = 0;
  if (!node || !node.IsScalar() || node.Tag() != "?" ||
      !YAML::convert<long long>::decode(node, value)) {
    return std::nullopt;
  }
  return value;
}

std::optional<double> number_of(const YAML::Node& node) {
  double value = 0.0;
  if (!node || !node.IsScalar() || node.Tag() != "?" ||
      !YAML::convert<double>::decode(node, value)) {
    return std::nullopt;
  }
  return value;
}

std::string value_shown(const YAML::Node& node) {
  if (!node || node.IsNull()) return "nothing";
  if (node.IsSequence()) return "a list of " + std::to_string(node.size()) + " entries";
  if (node.IsMap()) return "a mapping";
  if (const auto whole = whole_number_of(node)) return std::to_string(*whole);
  if (const auto number = number_of(node)) return number_text(*number);
  return "'" + node.Scalar() + "'";
}

namespace {

// OpenCV writes one document: the "%YAML:1.0" header, a "---" line, the keys. yaml-cpp reads only
// the first document of a file, so a second one (or a directive past the header) would be
// dropped without a word: it is refused instead.
void refuse_further_documents(const std::string& source, const std::string& text) {
  std::size_t line_start = text.find('\n');
  for (int line = 2; line_start != std::string::npos; ++line) {
    const std::size_t begin = line_start + 1;
    line_start = text.find('\n', begin);
    const std::string_view content = std::string_view(text).substr(
        begin, line_start == std::string::npos ? std::string::npos : line_start - begin);
    const bool document_start = line == 2 &&
                                content.find_first_not_of(" \t\r", 3) == std::string_view::npos &&
                                content.rfind("---", 0) == 0;
    if (document_start) continue;
    if (content.rfind('%', 0) == 0 || content.rfind("---", 0) == 0 ||
        content.rfind("...", 0) == 0) {
      throw_camera_error(source, "(file)",
                         "a YAML directive or document marker on line " + std::to_string(line) +
                             " ('" + std::string(content.substr(0, 20)) +
                             "'), expected one document: \"%YAML:1.0\", \"---\", then the keys");
    }
  }
}

}  // namespace

YAML::Node opencv_yaml_tree(const std::filesystem::path& path, const std::string& expected) {
  const std::string source = path.string();
  const std::string text = yaml_file_text(path, expected);
  if (text.rfind("%YAML", 0) != 0) {
    throw_camera_error(source, "(file)", "does not begin with \"%YAML:1.0\", expected " + expected);
  }
  refuse_further_documents(source, text);
  return checked_yaml_tree(source, text, expected);
}

CalibrationReader::CalibrationReader(std::string source, const YAML::Node& root)
    : source_(std::move(source)), root_(root) {
  if (!root_.IsMap()) {
    fail("(file)", "expected a mapping of calibration keys, got " + value_shown(root_));
  }
}

bool CalibrationReader::has(const char* key) const {
  const YAML::Node node = root_[key];
  return node && !node.IsNull();
}

void CalibrationReader::refuse_unknown_keys(std::initializer_list<const char*> known) const {
  for (const auto& entry : root_) {
    const std::string key = entry.first.Scalar();
    bool found = false;
    std::string expected;
    for (const char* name : known) {
      found = found || key == name;
      expected += (expected.empty() ? "" : ", ") + std::string(name);
    }
    if (!found) fail(key, "unknown key, expected one of " + expected);
  }
}

YAML::Node CalibrationReader::require(const char* key, const std::string& expected) const {
  if (!has(key)) fail(key, "missing, expected " + expected);
  return root_[key];
}

int CalibrationReader::image_size(const char* key) const {
  const std::string expected = "a whole number of pixels > 0";
  const YAML::Node node = require(key, expected);
  const auto value = whole_number_of(node);
  if (!value || *value <= 0 || *value > std::numeric_limits<int>::max()) {
    fail(key, value_shown(node) + ", expected " + expected);
  }
  return static_cast<int>(*value);
}

Matrix CalibrationReader::matrix(const char* key,
                                 std::initializer_list<std::pair<int, int>> shapes) const {
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

int CalibrationReader::side(const char* key, const YAML::Node& node, const char* name) const {
  const YAML::Node value = node[name];
  const auto whole = whole_number_of(value);
  if (!whole || *whole <= 0 || *whole > kMaxMatrixSide) {
    fail(key, std::string(name) + " is " + value_shown(value) + ", expected a whole number in 1.." +
                  std::to_string(kMaxMatrixSide));
  }
  return static_cast<int>(*whole);
}

Matrix CalibrationReader::matrix_of(const char* key, const YAML::Node& node,
                                    const std::string& expected) const {
  if (!node.IsMap()) fail(key, value_shown(node) + ", expected " + expected);
  Matrix m;
  m.rows = side(key, node, "rows");
  m.cols = side(key, node, "cols");
  const YAML::Node data = node["data"];
  const auto count = static_cast<std::size_t>(m.rows) * static_cast<std::size_t>(m.cols);
  if (!data || !data.IsSequence() || data.size() != count) {
    fail(key, "data is " + value_shown(data) + ", expected a list of " + std::to_string(count) +
                  " numbers for a " + m.shape() + " matrix");
  }
  for (std::size_t i = 0; i < count; ++i) {
    const YAML::Node entry = data[i];
    const std::string at = "entry (" + std::to_string(i / static_cast<std::size_t>(m.cols)) + ", " +
                           std::to_string(i % static_cast<std::size_t>(m.cols)) + ")";
    const auto value = number_of(entry);
    if (!value) fail(key, at + " is " + value_shown(entry) + ", expected a number");
    if (!std::isfinite(*value)) {
      fail(key, at + " is " + number_text(*value) + ", expected a finite number");
    }
    m.values.push_back(*value);
  }
  return m;
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
