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
    case CameraFault::kUnavailable:
      return "camera unavailable";
    case CameraFault::kStopped:
      return "camera stopped delivering";
    case CameraFault::kCorruptFrame:
      return "corrupt frame";
    case CameraFault::kOutOfSync:
      return "exposure out of sync";
  }
  return "unknown fault";
}

HealthReport camera_fault_report(const std::string& camera_name, CameraFault fault,
                                 const std::string& detail) {
  return HealthReport{fault,
                      "camera '" + camera_name + "': " + to_string(fault) + " (" + detail + ")"};
}

}  // namespace safecell
