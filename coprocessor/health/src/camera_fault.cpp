#include "safecell/health/camera_fault.hpp"

namespace safecell {

const char* to_string(CameraFault fault) {
  switch (fault) {
    case CameraFault::kNone:
      return "healthy";
    case CameraFault::kWrongFormat:
      return "wrong frame format";
    case CameraFault::kBlack:
      return "black image";
    case CameraFault::kSaturated:
      return "saturated image";
    case CameraFault::kFrozen:
      return "frozen image";
    case CameraFault::kLightingChange:
      return "sudden lighting change";
    case CameraFault::kMoved:
      return "camera moved";
  }
  return "unknown fault";
}

}  // namespace safecell
