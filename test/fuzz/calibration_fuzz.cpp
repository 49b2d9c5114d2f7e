// Any bytes as a camera calibration file (OpenCV YAML), read as `safecell` reads one: from a
// file, through the yaml-cpp gate, then OpenCV's parser. A refusal is a CameraError; anything
// else (an OpenCV exception that escaped, a crash in its parser) is a finding.

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "fuzz_targets.hpp"
#include "safecell/camera/calibration_file.hpp"
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
  try {
    static_cast<void>(read_camera_calibration(file, "fuzzed"));
  } catch (const CameraError&) {
  }
  return 0;
}

}  // namespace safecell::fuzz

SAFECELL_FUZZ_ENTRY_POINT(calibration)
