#pragma once
// The checks every YAML file the camera module reads passes before a parser that recurses (or
// answers one of two equal keys) sees it: calibrations, poses, ROS camera_info and MC-Calib files.
// Private to the camera module.

#include <yaml-cpp/yaml.h>

#include <filesystem>
#include <string>

namespace safecell {

// The file's bytes: it must exist, be no folder and hold at most 4 MiB. Throws CameraError naming
// the file and `expected` (what the file should have been).
std::string yaml_file_text(const std::filesystem::path& path, const std::string& expected);

// The text as yaml-cpp reads it (it refuses nesting beyond its own limit instead of recursing on),
// walked without recursion: nesting deeper than 16 levels, a key without a name, or a key given
// twice in any mapping (OpenCV would answer one of them) throws CameraError.
YAML::Node checked_yaml_tree(const std::string& source, const std::string& text,
                             const std::string& expected);

}  // namespace safecell
