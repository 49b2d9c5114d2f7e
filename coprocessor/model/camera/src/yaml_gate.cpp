#include "yaml_gate.hpp"

#include <yaml-cpp/depthguard.h>

#include <cstdint>
#include <fstream>
#include <map>
#include <sstream>
#include <utility>
#include <vector>

#include "safecell/camera/camera_error.hpp"

namespace safecell {
namespace {

// Larger is no calibration: MC-Calib's file of a dozen cameras and boards is tens of kB.
constexpr std::uintmax_t kMaxCalibrationBytes = std::uintmax_t{4} << 20;
// Calibration files nest three deep (a file, a matrix, its data); OpenCV's own YAML parser
// recurses once per level and overflows its stack on files nested some 100,000 deep.
constexpr int kMaxCalibrationDepth = 16;

}  // namespace

std::string yaml_file_text(const std::filesystem::path& path, const std::string& expected) {
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
  return text.str();
}

YAML::Node checked_yaml_tree(const std::string& source, const std::string& text,
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
  return root;
}

}  // namespace safecell
