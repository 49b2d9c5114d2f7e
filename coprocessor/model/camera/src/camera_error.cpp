#include "safecell/camera/camera_error.hpp"

namespace safecell {

void throw_camera_error(const std::string& source, const std::string& field,
                        const std::string& problem) {
  throw CameraError(source + ": " + field + ": " + problem);
}

}  // namespace safecell
