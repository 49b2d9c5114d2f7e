#pragma once
// An incident folder: what the incident recorder writes (incident_recorder.hpp) and
// `safecell replay` reads. A folder that exists is whole (it is renamed into place when written):
//   incident.json              the format, the causes, the trigger time, the setup (the cell file
//                              with its grid and LUT fingerprints, the cameras' sync allowance),
//                              the cameras, and per cycle: the exposure, each camera's exposure
//                              and view (a health fault by name), the pose, the map's size
//   cell.yaml                  the cell file's text as the service read it
//   reference/<camera>.png     the reference images the service compared with
//   frames/<camera>/<cycle>.png and frame_times.csv (an image folder source reads it too); a
//                              camera that delivered nothing that cycle has no file
//   maps/<cycle>.bits          the forbidden map sent: its cell bits as little-endian 64-bit words
//   joints.csv                 time_s, state, speed_scale, q_rad, velocity_rad_s (per joint,
//                              space-separated)
// Times are seconds since the run began, on the service's clock.

#include <cstdint>
#include <filesystem>
#include <opencv2/core/mat.hpp>
#include <optional>
#include <string>
#include <vector>

#include "safecell/acquisition/frame_set.hpp"
#include "safecell/cellsets/cell_set.hpp"

namespace safecell {

inline constexpr const char* kIncidentFormat = "safecell incident 1";

// What the service ran with; replay needs the same to give the same maps.
struct IncidentSetup {
  std::filesystem::path cell_file;  // as the service was started with it, absolute
  std::string cell_text;            // its text then
  std::uint64_t grid_fingerprint = 0;
  std::uint64_t lut_fingerprint = 0;
  double sync_error_s = 0.0;       // the pipeline's allowance for exposure differences
  std::vector<cv::Mat> reference;  // per camera, written only (replay reads them by the cell)
};

// One camera in one cycle.
struct IncidentView {
  std::optional<double> exposure_s;  // nullopt: the camera delivered no frame (no file)
  CameraFault fault = CameraFault::kNone;
  std::string detail;  // the health fault's detail
};

struct IncidentCycle {
  std::uint64_t index = 0;  // the service's cycle number (the files' names)
  double exposure_s = 0.0;  // the frame set's median exposure
  bool pose_known = false;
  std::vector<double> q;  // the robot at the exposure (rad), when known
  std::uint32_t known_views = 0;
  std::size_t forbidden_cells = 0;
  std::string all_forbidden;        // why the whole map was forbidden; empty: it was not
  std::vector<IncidentView> views;  // per camera
};

struct IncidentJointState {
  double time_s = 0.0;
  std::string state;  // the controller's state by name (moving, slowed, stopped, fault, ...)
  double speed_scale = 0.0;
  std::vector<double> q;
  std::vector<double> velocity;  // rad/s, empty when not reported
};

// Why the controller slowed down or stopped (the service's stop explanation).
struct IncidentExplanation {
  double time_s = 0.0;
  std::string text;
};

struct Incident {
  std::vector<std::string> causes;
  double trigger_s = 0.0;
  IncidentSetup setup;  // without the reference images
  std::vector<std::string> cameras;
  std::vector<IncidentCycle> cycles;
  std::vector<IncidentJointState> joints;
};

// Reads incident.json, cell.yaml and joints.csv. Throws FileError naming the file and the field
// (and the line in joints.csv) for anything missing or malformed, or for another format.
Incident read_incident(const std::filesystem::path& folder);

// The frames of one cycle as the cameras delivered them: images from frames/, exposures and
// views from incident.json. Throws FileError for a missing or unreadable image.
FrameSet incident_frame_set(const std::filesystem::path& folder, const Incident& incident,
                            const IncidentCycle& cycle);

// maps/<cycle>.bits as a set of `cell_count` cells. Throws FileError when it is missing or of
// another size.
CellSet read_incident_map(const std::filesystem::path& folder, const IncidentCycle& cycle,
                          std::uint32_t cell_count);

// The files' names, for the recorder and the reader alike.
std::filesystem::path incident_frame_file(const std::filesystem::path& folder,
                                          const std::string& camera, std::uint64_t cycle);
std::filesystem::path incident_map_file(const std::filesystem::path& folder, std::uint64_t cycle);

// A fingerprint as the incident's setup writes it (hexadecimal, no prefix), for the recorder and
// for messages that compare one with it.
std::string fingerprint_hex(std::uint64_t fingerprint);

}  // namespace safecell
