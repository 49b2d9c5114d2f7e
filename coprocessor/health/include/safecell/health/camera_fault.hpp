#pragma once
// Why a camera's view cannot be trusted.

#include <string>

namespace safecell {

enum class CameraFault {
  kNone,
  kWrongFormat,     // empty frame, not 8-bit gray, or not the camera's size
  kBlack,           // covered lens, lamp off, sensor dead
  kSaturated,       // blinded by a light or the sun
  kFrozen,          // identical frames, or less noise than a live sensor shows
  kLightingChange,  // the scene's brightness jumped away from the reference's
  kMoved,           // the image no longer lines up with the reference
};

const char* to_string(CameraFault fault);

struct HealthReport {
  CameraFault fault = CameraFault::kNone;
  std::string detail;  // the measured figure and the limit it broke, for the log

  bool healthy() const { return fault == CameraFault::kNone; }
};

}  // namespace safecell
