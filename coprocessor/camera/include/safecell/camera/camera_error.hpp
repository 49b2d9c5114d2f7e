#pragma once
// The one exception type of the camera module. Its message is a single line that names the
// source (a calibration file, or "camera 'cam0'"), the field or key, the value, and what was
// expected; the CLI prints it as it is.

#include <stdexcept>
#include <string>

namespace safecell {

class CameraError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Builds "source: field: problem".
[[noreturn]] void throw_camera_error(const std::string& source, const std::string& field,
                                     const std::string& problem);

}  // namespace safecell
