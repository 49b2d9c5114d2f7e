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
  kUnavailable,     // the camera (device, file, folder, stream) could not be opened
  kStopped,         // the camera was open but delivered no frame when asked
  kCorruptFrame,    // the frame could not be decoded (a truncated or garbage image file)
  kOutOfSync,       // exposed too far from the other cameras of its frame set
};

const char* to_string(CameraFault fault);

struct HealthReport {
  CameraFault fault = CameraFault::kNone;
  std::string detail;  // the measured figure and the limit it broke, for the log

  bool healthy() const { return fault == CameraFault::kNone; }
};

// The report of `fault` on camera `camera_name`, its detail reading
// "camera '<name>': <to_string(fault)> (<detail>)" so that every log line names the camera.
HealthReport camera_fault_report(const std::string& camera_name, CameraFault fault,
                                 const std::string& detail);

}  // namespace safecell
