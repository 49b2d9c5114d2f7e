#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <cmath>
#include <iterator>
#include <vector>

#include "camera_checks.hpp"
#include "error_text.hpp"
#include "safecell/camera/calibration_import.hpp"
#include "safecell/camera/camera_error.hpp"
#include "yaml_gate.hpp"

namespace safecell {
namespace {

// What camera_calibration writes (the last two are read by no one here, see the header).
constexpr const char* kKeys[] = {"image_width",          "image_height",
                                 "camera_name",          "camera_matrix",
                                 "distortion_model",     "distortion_coefficients",
                                 "rectification_matrix", "projection_matrix"};

class RosReader {
 public:
  RosReader(std::string source, const YAML::Node& root) : source_(std::move(source)), root_(root) {
    if (!root_.IsMap()) fail("(file)", "expected a mapping of camera_info keys");
    // A misspelt key would otherwise be passed over (and its value taken from nowhere).
    for (const auto& entry : root_) {
      const std::string key = entry.first.Scalar();
      if (std::find(std::begin(kKeys), std::end(kKeys), key) == std::end(kKeys)) {
        std::string expected;
        for (const char* known : kKeys)
          expected += (expected.empty() ? "" : ", ") + std::string(known);
        fail(key, "unknown key, expected one of " + expected);
      }
    }
  }

  [[noreturn]] void fail(const std::string& key, const std::string& problem) const {
    throw_camera_error(source_, key, problem);
  }

  YAML::Node require(const char* key, const std::string& expected) const {
    const YAML::Node node = root_[key];
    if (!node) fail(key, "missing, expected " + expected);
    return node;
  }

  int image_size(const char* key) const {
    const YAML::Node node = require(key, "a whole number of pixels > 0");
    int value = 0;
    if (!node.IsScalar() || !YAML::convert<int>::decode(node, value) || value <= 0) {
      fail(key, "'" + (node.IsScalar() ? node.Scalar() : std::string("not a number")) +
                    "', expected a whole number of pixels > 0");
    }
    return value;
  }

  std::string text(const char* key, const std::string& expected) const {
    const YAML::Node node = require(key, expected);
    if (!node.IsScalar()) fail(key, "not a text, expected " + expected);
    return node.Scalar();
  }

  // {rows, cols, data}: the data, a list of finite numbers whose count is one of `counts` (rows and
  // cols, which ROS writes too, are not needed).
  std::vector<double> matrix(const char* key, const std::vector<std::size_t>& counts) const {
    const std::string expected = "a mapping of rows, cols and data (a list of numbers)";
    const YAML::Node node = require(key, expected);
    if (!node.IsMap()) fail(key, "expected " + expected);
    for (const auto& entry : node) {
      const std::string name = entry.first.Scalar();
      if (name != "rows" && name != "cols" && name != "data") {
        fail(key, "unknown key '" + name + "', expected rows, cols and data");
      }
    }
    const YAML::Node data = node["data"];
    if (!data || !data.IsSequence()) fail(key, "expected " + expected);
    std::vector<double> values;
    for (std::size_t i = 0; i < data.size(); ++i) {
      double value = 0.0;
      if (!data[i].IsScalar() || !YAML::convert<double>::decode(data[i], value) ||
          !std::isfinite(value)) {
        fail(key, "data entry " + std::to_string(i) + " is not a finite number");
      }
      values.push_back(value);
    }
    bool allowed = false;
    std::string counts_text;
    for (const std::size_t count : counts) {
      allowed = allowed || values.size() == count;
      counts_text += (counts_text.empty() ? "" : " or ") + std::to_string(count);
    }
    if (!allowed) {
      fail(key,
           "data holds " + std::to_string(values.size()) + " numbers, expected " + counts_text);
    }
    return values;
  }

 private:
  std::string source_;
  YAML::Node root_;
};

}  // namespace

CameraIntrinsics read_ros_camera_info(const std::filesystem::path& path) {
  const std::string source = path.string();
  const std::string expected = "a ROS camera_info YAML file";
  const RosReader reader(source,
                         checked_yaml_tree(source, yaml_file_text(path, expected), expected));
  CameraIntrinsics intrinsics;
  intrinsics.width_px = reader.image_size("image_width");
  intrinsics.height_px = reader.image_size("image_height");
  const std::vector<double> k = reader.matrix("camera_matrix", {9});
  if (k[1] != 0.0 || k[3] != 0.0 || k[6] != 0.0 || k[7] != 0.0 || k[8] != 1.0) {
    reader.fail("camera_matrix",
                "data is " + matrix_text(Eigen::Map<const Eigen::Matrix3d>(k.data()).transpose()) +
                    ", expected [fx 0 cx; 0 fy cy; 0 0 1] (no skew)");
  }
  intrinsics.fx_px = k[0];
  intrinsics.cx_px = k[2];
  intrinsics.fy_px = k[4];
  intrinsics.cy_px = k[5];
  const std::string model = reader.text("distortion_model", "plumb_bob");
  if (model != "plumb_bob") {
    reader.fail("distortion_model",
                "'" + model + "', expected plumb_bob (OpenCV's k1 k2 p1 p2 k3)");
  }
  const std::vector<double> d = reader.matrix("distortion_coefficients", {4, 5});
  intrinsics.distortion = {d[0], d[1], d[2], d[3], d.size() == 5 ? d[4] : 0.0};
  check_camera_values(
      source,
      {"image_width", "image_height", "camera_matrix (fx)", "camera_matrix (fy)",
       "camera_matrix (cx)", "camera_matrix (cy)", "distortion_coefficients", "", ""},
      intrinsics, Eigen::Matrix3d::Identity(), Eigen::Vector3d::Zero());
  return intrinsics;
}

}  // namespace safecell
