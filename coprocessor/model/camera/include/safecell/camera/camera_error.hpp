#pragma once
// The one exception type of the camera module. Its message is a single line that names the
// source (a calibration file, or "camera 'cam0'"), the field or key, the value, and what was
// expected; the CLI prints it as it is.

#include <stdexcept>
#include <string>

#include "safecell/errors/input_error.hpp"

namespace safecell {

class CameraError : public InputError {
 public:
  using InputError::InputError;
};

// Builds "source: field: problem".
[[noreturn]] void throw_camera_error(const std::string& source, const std::string& field,
                                     const std::string& problem);

}  // namespace safecell
