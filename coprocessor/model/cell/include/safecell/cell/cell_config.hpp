#pragma once
// The cell description as read from a cell file: what the C-space grid and (in later issues) the
// robot, cameras and obstacles are built from. Every value remembers the line it came from, so a
// value refused later can still be named in the file.

#include <array>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "safecell/geometry/shape.hpp"

namespace safecell {

struct SourceLine {
  std::string source;  // file path, or "built-in default cell"
  int line = 0;        // 1-based; 0 when unknown
};

struct JointConfig {
  std::string name;
  // With a robot, the range defaults to the arm's limits and may only narrow them, and l_m is
  // computed from the model; without one, both are given.
  std::optional<std::array<double, 2>> range_deg;
  std::optional<double> l_m;
  bool discretised = true;
  SourceLine at;
  SourceLine range_at;
  SourceLine l_at;
};

inline constexpr const char* kBuiltinRobotPrefix = "builtin:";

struct RobotConfig {
  // A URDF path (relative paths are resolved against the cell file's folder when it is read),
  // or "builtin:rx130_class" for the project's own arm.
  std::string urdf;
  std::string tool_link;   // where the chain ends; empty: the deepest leaf of the URDF
  std::string tool_frame;  // the frame the tool hangs from; empty: the last movable link
  std::array<double, 3> tool_point_m{0.0, 0.0, 0.0};
  std::vector<PlacedShape> tool_shapes;  // in the tool frame; they join the robot's geometry
  // Shapes for URDF links that have no collision geometry, in each link's frame: a moving link
  // without geometry is refused unless it is named here on purpose.
  std::map<std::string, std::vector<PlacedShape>> collision_stand_ins;
  SourceLine at;
};

// A static obstacle: a box standing in the cell (tables, fences, machines). It never appears in
// the difference images, so it enters the forbidden map from its geometry.
struct BoxObstacleConfig {
  std::string name;
  std::array<double, 3> size_m{0.0, 0.0, 0.0};
  std::array<double, 3> centre_m{0.0, 0.0, 0.0};
  double yaw_deg = 0.0;  // turn about the vertical axis
  SourceLine at;
};

// A camera placed by where it stands and what it looks at (no lens distortion).
struct LookAtConfig {
  std::array<double, 3> position_m{0.0, 0.0, 0.0};
  std::array<double, 3> target_m{0.0, 0.0, 0.0};
  double horizontal_fov_deg = 0.0;
  int width_px = 0;
  int height_px = 0;
};

// Where a camera's frames come from when the service runs on real cameras (`safecell run`).
struct CameraSourceConfig {
  enum class Kind {
    kDevice,       // a capture device by index (V4L2 on Linux): `device: 0`
    kVideoFile,    // `video: path` (relative to the cell file's folder)
    kImageFolder,  // `folder: path`: image files in name order, times from frame_times.csv
    kGstreamer,    // `gstreamer: "... ! appsink"`: a GStreamer pipeline ending in an appsink
    kStream,       // `url: rtsp://...`: a network stream
  };
  Kind kind = Kind::kDevice;
  std::string spec;  // the device index as text, the resolved path, the pipeline or the URL
  SourceLine at;
};

struct CameraConfig {
  std::string name;
  // Exactly one of: an OpenCV calibration YAML (path resolved against the cell file's folder),
  // or a look-at placement.
  std::string calibration;
  std::optional<LookAtConfig> look_at;
  std::optional<CameraSourceConfig> source;  // unset: simulated or replayed cameras only
  SourceLine at;
};

struct FeatureGridConfig {
  int columns = 64;
  int rows = 64;
  SourceLine at;
};

// How a feature cell counts as blocked: weighted feature distance to the reference above the
// threshold. Unset values take the defaults of the features module.
struct BlockedCellConfig {
  std::optional<std::array<int, 5>> weights;  // average, variance, span, contrast, edge_count
  std::optional<int> threshold;
  SourceLine at;
};

// An opening in the cell's fence where people come in: a span along one wall. Outside the
// entries the walls are closed, so a person is first seen at an entry (ISO 13855's detection
// zone boundary) and the robot is kept the separation distance away from each (entry_zones.hpp).
enum class CellWall { kMinusX, kPlusX, kMinusY, kPlusY };

struct EntryConfig {
  std::string name;
  CellWall wall = CellWall::kMinusX;
  // Along the wall: the y range of an x wall, the x range of a y wall; metres, from < to.
  std::array<double, 2> span_m{0.0, 0.0};
  SourceLine at;
};

// ISO 13855's minimum distance S = K * (t_response + t_stop) + C: kept between the robot and
// every entry (entry_separation), and between the robot and every person the cameras see in the
// cell (protective_separation).
struct SeparationDistanceConfig {
  double approach_speed_m_s = 1.6;  // K: people walk in at up to this speed
  double response_s = 0.1;          // a person crossing the entry -> the stop command
  double stopping_s = 0.3;          // the robot's stopping time from its top speed
  double intrusion_m = 0.2;         // C: a hand or arm reaching ahead of the body
  SourceLine at;
};

// The protective separation's defaults: ISO 13855's walking speed, a response of 0.1 s (a frame
// period, the processing and the link) and a stop of 0.3 s, and no intrusion C: S = 0.64 m.
inline constexpr double kMaxProtectiveSeparation_m = 0.95;
inline SeparationDistanceConfig default_protective_separation() {
  SeparationDistanceConfig separation;
  separation.intrusion_m = 0.0;
  return separation;
}

// The reduced speeds by default: half and a quarter of the top speed (S = 0.40 m and 0.28 m with
// the default distance).
inline constexpr double kMinReducedSpeed = 0.05;
inline constexpr double kMaxReducedSpeed = 0.95;
inline std::vector<double> default_reduced_speeds() { return {0.5, 0.25}; }

struct CellConfig {
  std::string name;
  std::string source;
  double m_max_m = 0.0;
  SourceLine m_max_at;
  std::optional<RobotConfig> robot;
  std::vector<JointConfig> joints;
  SourceLine joints_at;
  // The cell's inside: floor centre at the origin, z up; walls at +-x/2, +-y/2.
  std::array<double, 3> size_m{4.0, 4.0, 3.0};
  SourceLine size_at;
  std::vector<CameraConfig> cameras;
  SourceLine cameras_at;
  std::vector<BoxObstacleConfig> obstacles;
  FeatureGridConfig feature_grid;
  BlockedCellConfig blocked_cells;
  // A configuration is critical when at least this many cameras see it blocked (paper §4.4).
  // Unset: 2, or 1 with a single camera. Above 2, a person whom the arm hides from some cameras
  // needs an occlusion reach that fills them in (docs/validation.md, "The camera threshold").
  std::optional<int> camera_threshold;
  SourceLine camera_threshold_at;
  // How far, in feature cells, a person's blob in a camera's view is grown into the robot's
  // silhouette, where the arm may hide the rest of them (occlusion-aware robot removal,
  // robot_removal.hpp). Unset: the fusion's default.
  std::optional<int> occlusion_reach_cells;
  SourceLine occlusion_reach_at;
  // The largest motion, in metres, of the sub-cells whose envelopes draw a cell's silhouette
  // (model_silhouettes.hpp): each discretised joint's cell is cut into ceil(m_max_m / this) equal
  // sub-cells, at most kMaxEnvelopeSubdivision (cell_model.hpp). Unset, or m_max_m or more: whole
  // cells.
  std::optional<double> envelope_max_move_m;
  SourceLine envelope_max_move_at;
  // The size of the balls that cover the robot's surface in the tables, robot removal and the
  // protective separation (robot_balls.hpp), metres. Unset: kDefaultBallRadius_m (cell_model.hpp).
  std::optional<double> ball_radius_m;
  SourceLine ball_radius_at;
  // The robot parts the cameras vote on (robot_parts.hpp): "per-link", "links-and-wrist",
  // "arm-segments" or "whole-robot" (the paper's vote). Unset: arm segments.
  std::optional<std::string> robot_parts;
  SourceLine robot_parts_at;
  // Blind spots (floor positions too few cameras see a person at, floor_coverage.hpp): `forbid`
  // (the default) makes every C-space cell whose envelope reaches into one a static obstacle
  // cell; `allow` leaves them, with a warning whenever the tables are loaded.
  bool forbid_blind_spots = true;
  SourceLine blind_spots_at;
  // Where people come in. Unset: the cell does not say, so people may step in anywhere along
  // the walls (a warning whenever the tables are loaded); set: at least one entry.
  std::optional<std::vector<EntryConfig>> entries;
  SourceLine entries_at;
  SeparationDistanceConfig entry_separation;
  // The protective separation check (protective_separation.hpp): when the cameras see someone
  // within this distance of the robot, the robot slows down or stops. Unset (`off`): not
  // checked. Its intrusion C defaults to 0 (the cameras see an arm reaching out, unlike an
  // entry's boundary).
  std::optional<SeparationDistanceConfig> protective_separation;
  SourceLine protective_separation_at;
  // Its reduced speeds (protective_separation.reduced_speeds), fractions of the top speed,
  // descending, each in kReducedSpeedRange: at speed f the robot stops within f * stopping_s, so
  // someone may come as near as S(f) = K * (t_response + f * t_stop) + C before it must slow
  // further; nearer than the last level's S it stops (the whole map forbidden). Empty: it stops
  // at S.
  std::vector<double> protective_reduced_speeds = default_reduced_speeds();
};

}  // namespace safecell
