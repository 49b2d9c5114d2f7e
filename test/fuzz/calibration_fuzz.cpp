// Any bytes as a camera calibration file, read as `safecell` reads one from a file (the yaml-cpp
// gate, then OpenCV's parser) by every reader of the family: the calibration, the pose keys alone
// (`camera import --pose`), a ROS camera_info file and an MC-Calib result. A refusal is a
// CameraError; anything else (an OpenCV exception that escaped, a crash in a parser) is a
// finding.

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "fuzz_targets.hpp"
#include "safecell/camera/calibration_file.hpp"
#include "safecell/camera/calibration_import.hpp"
#include "safecell/camera/camera_error.hpp"

namespace safecell::fuzz {

int calibration(const std::uint8_t* data, std::size_t size) {
  static const std::filesystem::path file =
      std::filesystem::temp_directory_path() /
      ("safecell-fuzz-calibration-" + std::to_string(::getpid()) + ".yaml");
  {
    std::ofstream out(file, std::ios::binary | std::ios::trunc);
    out.write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
  }
  // Every reader of this family, each on its own: a refusal by one must not hide another's crash.
  try {
    static_cast<void>(read_camera_calibration(file, "fuzzed"));
  } catch (const CameraError&) {
  }
  try {
    static_cast<void>(read_cell_pose(file));
  } catch (const CameraError&) {
  }
  try {
    static_cast<void>(read_ros_camera_info(file));
  } catch (const CameraError&) {
  }
  try {
    static_cast<void>(read_mc_calib_cameras(file, 0.001));
  } catch (const CameraError&) {
  }
  return 0;
}

}  // namespace safecell::fuzz

SAFECELL_FUZZ_ENTRY_POINT(calibration)
