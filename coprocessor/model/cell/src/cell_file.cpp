#include "safecell/cell/cell_file.hpp"

#include <yaml-cpp/depthguard.h>
#include <yaml-cpp/yaml.h>

#include <Eigen/Geometry>
#include <cmath>
#include <fstream>
#include <numbers>
#include <optional>
#include <sstream>

#include "safecell/cell/cell_error.hpp"
#include "safecell/cell/default_cell.hpp"
#include "safecell/cell/entry_zones.hpp"
#include "yaml_field.hpp"

namespace safecell {
namespace {

std::array<double, 3> triple_of(const Field& field, const char* expected) {
  const auto values = numbers_of(field, 3, expected);
  return {values[0], values[1], values[2]};
}

std::string resolved(const std::string& path, const std::filesystem::path& base_directory) {
  return std::filesystem::path(path).is_relative()
             ? (base_directory / path).lexically_normal().string()
             : path;
}

JointConfig joint_of(const Field& field) {
  require_mapping(field);
  refuse_unknown_keys(field, {"name", "range_deg", "l_m", "discretised"});
  JointConfig joint;
  joint.at = field.at;
  joint.name = text_of(require(field, "name"));
  if (field.node["range_deg"]) {
    const Field range = require(field, "range_deg");
    const auto values = numbers_of(range, 2, "[lower, upper] in degrees");
    joint.range_deg = std::array<double, 2>{values[0], values[1]};
    joint.range_at = range.at;
  }
  if (field.node["l_m"]) {
    const Field lever = require(field, "l_m");
    joint.l_m = number_of(lever);
    joint.l_at = lever.at;
  }
  if (field.node["discretised"]) joint.discretised = flag_of(require(field, "discretised"));
  return joint;
}

template <typename Item, typename Read>
std::vector<Item> list_of(const Field& field, Read read) {
  if (!field.node.IsSequence()) {
    throw_cell_error(field.at, field.path, "expected a list, got " + shown(field.node));
  }
  std::vector<Item> items;
  for (std::size_t i = 0; i < field.node.size(); ++i) items.push_back(read(element(field, i)));
  return items;
}

double positive_of(const Field& field) {
  const double value = number_of(field);
  if (!(std::isfinite(value) && value > 0.0)) {
    throw_cell_error(field.at, field.path, "value " + field.node.Scalar() + ", expected above 0");
  }
  return value;
}

// One tool shape: exactly one of box, sphere, cylinder, capsule, and where it sits in the tool
// frame (origin_m, rpy_deg: roll, pitch, yaw about x, y, z as in URDF).
PlacedShape tool_shape_of(const Field& field) {
  require_mapping(field);
  refuse_unknown_keys(field, {"box", "sphere", "cylinder", "capsule", "origin_m", "rpy_deg"});
  const int kinds = (field.node["box"] ? 1 : 0) + (field.node["sphere"] ? 1 : 0) +
                    (field.node["cylinder"] ? 1 : 0) + (field.node["capsule"] ? 1 : 0);
  if (kinds != 1) {
    throw_cell_error(field.at, field.path,
                     "expected exactly one of box, sphere, cylinder and capsule");
  }
  PlacedShape placed;
  if (field.node["box"]) {
    const Field box = require(field, "box");
    require_mapping(box);
    refuse_unknown_keys(box, {"size_m"});
    const Field size = require(box, "size_m");
    // Checks the shape of the list first, then each edge on its own line of the message.
    static_cast<void>(numbers_of(size, 3, "[x, y, z] edge lengths in metres"));
    placed.shape = Box{{positive_of(element(size, 0)), positive_of(element(size, 1)),
                        positive_of(element(size, 2))}};
  } else if (field.node["sphere"]) {
    const Field sphere = require(field, "sphere");
    require_mapping(sphere);
    refuse_unknown_keys(sphere, {"radius_m"});
    placed.shape = Sphere{positive_of(require(sphere, "radius_m"))};
  } else {
    const bool cylinder = static_cast<bool>(field.node["cylinder"]);
    const Field round = require(field, cylinder ? "cylinder" : "capsule");
    require_mapping(round);
    refuse_unknown_keys(round, {"radius_m", "length_m"});
    const double radius = positive_of(require(round, "radius_m"));
    const double length = positive_of(require(round, "length_m"));
    if (cylinder) {
      placed.shape = Cylinder{radius, length};
    } else {
      placed.shape = Capsule{radius, length};
    }
  }
  if (field.node["origin_m"]) {
    const auto origin = numbers_of(require(field, "origin_m"), 3, "[x, y, z] in metres");
    placed.pose.translation() = Eigen::Vector3d(origin[0], origin[1], origin[2]);
  }
  if (field.node["rpy_deg"]) {
    const auto rpy = numbers_of(require(field, "rpy_deg"), 3, "[roll, pitch, yaw] in degrees");
    const double to_rad = std::numbers::pi / 180.0;
    placed.pose.linear() = (Eigen::AngleAxisd(rpy[2] * to_rad, Eigen::Vector3d::UnitZ()) *
                            Eigen::AngleAxisd(rpy[1] * to_rad, Eigen::Vector3d::UnitY()) *
                            Eigen::AngleAxisd(rpy[0] * to_rad, Eigen::Vector3d::UnitX()))
                               .toRotationMatrix();
  }
  return placed;
}

RobotConfig robot_of(const Field& field, const std::filesystem::path& base_directory) {
  require_mapping(field);
  refuse_unknown_keys(field, {"urdf", "tool_link", "tool", "collision_stand_ins"});
  RobotConfig robot;
  robot.at = field.at;
  robot.urdf = text_of(require(field, "urdf"));
  if (robot.urdf.rfind(kBuiltinRobotPrefix, 0) != 0)
    robot.urdf = resolved(robot.urdf, base_directory);
  if (field.node["tool_link"]) robot.tool_link = text_of(require(field, "tool_link"));
  if (field.node["tool"]) {
    const Field tool = require(field, "tool");
    require_mapping(tool);
    refuse_unknown_keys(tool, {"frame", "point_m", "shapes"});
    if (tool.node["frame"]) robot.tool_frame = text_of(require(tool, "frame"));
    if (tool.node["point_m"]) {
      robot.tool_point_m = triple_of(require(tool, "point_m"), "[x, y, z] in metres");
    }
    if (tool.node["shapes"]) {
      robot.tool_shapes = list_of<PlacedShape>(require(tool, "shapes"), tool_shape_of);
    }
  }
  if (field.node["collision_stand_ins"]) {
    const Field stand_ins = require(field, "collision_stand_ins");
    require_mapping(stand_ins);
    refuse_repeated_keys(stand_ins);
    for (const auto& entry : stand_ins.node) {
      const std::string link = entry.first.Scalar();
      robot.collision_stand_ins[link] =
          list_of<PlacedShape>(require(stand_ins, link), tool_shape_of);
    }
  }
  return robot;
}

BoxObstacleConfig obstacle_of(const Field& field) {
  require_mapping(field);
  refuse_unknown_keys(field, {"name", "size_m", "centre_m", "yaw_deg"});
  BoxObstacleConfig box;
  box.at = field.at;
  box.name = text_of(require(field, "name"));
  box.size_m = triple_of(require(field, "size_m"), "[x, y, z] edge lengths in metres");
  box.centre_m = triple_of(require(field, "centre_m"), "[x, y, z] in metres");
  if (field.node["yaw_deg"]) box.yaw_deg = number_of(require(field, "yaw_deg"));
  return box;
}

// A number in [lo, hi] (units in the message's `expected`).
double bounded_of(const Field& field, double lo, double hi, const char* expected) {
  const double value = number_of(field);
  if (!(std::isfinite(value) && value >= lo && value <= hi)) {
    throw_cell_error(field.at, field.path,
                     "value " + field.node.Scalar() + ", expected " + std::string(expected));
  }
  return value;
}

// One entry: {name, wall: -x | +x | -y | +y, span_m: [from, to]} along a wall of a cell of
// `size_m`.
EntryConfig entry_of(const Field& field, const std::array<double, 3>& size_m) {
  require_mapping(field);
  refuse_unknown_keys(field, {"name", "wall", "span_m"});
  EntryConfig entry;
  entry.at = field.at;
  entry.name = text_of(require(field, "name"));
  const Field wall = require(field, "wall");
  const std::string side = text_of(wall);
  if (side == "-x") {
    entry.wall = CellWall::kMinusX;
  } else if (side == "+x") {
    entry.wall = CellWall::kPlusX;
  } else if (side == "-y") {
    entry.wall = CellWall::kMinusY;
  } else if (side == "+y") {
    entry.wall = CellWall::kPlusY;
  } else {
    throw_cell_error(wall.at, wall.path, "value '" + side + "', expected -x, +x, -y or +y");
  }
  const Field span = require(field, "span_m");
  const auto values = numbers_of(span, 2, "[from, to] along the wall in metres");
  const bool x_wall = entry.wall == CellWall::kMinusX || entry.wall == CellWall::kPlusX;
  const double half = (x_wall ? size_m[1] : size_m[0]) / 2.0;
  if (!(values[0] < values[1] && values[0] >= -half && values[1] <= half)) {
    std::ostringstream expected;
    expected << "[from, to] with -" << half << " <= from < to <= " << half
             << " (the wall's extent in metres)";
    throw_cell_error(span.at, span.path,
                     "value [" + span.node[0].Scalar() + ", " + span.node[1].Scalar() +
                         "], expected " + expected.str());
  }
  entry.span_m = {values[0], values[1]};
  return entry;
}

// `defaults`: what a field left out keeps.
SeparationDistanceConfig separation_distance_of(const Field& field,
                                                SeparationDistanceConfig separation,
                                                bool with_reduced_speeds = false) {
  require_mapping(field);
  if (with_reduced_speeds) {
    refuse_unknown_keys(
        field, {"approach_speed_m_s", "response_s", "stopping_s", "intrusion_m", "reduced_speeds"});
  } else {
    refuse_unknown_keys(field, {"approach_speed_m_s", "response_s", "stopping_s", "intrusion_m"});
  }
  separation.at = field.at;
  // Each field is optional: absent, it keeps its default.
  const auto read = [&field](const char* key, double& value, double lo, double hi,
                             const char* expected) {
    if (field.node[key]) value = bounded_of(require(field, key), lo, hi, expected);
  };
  // ISO 13855 allows no slower approach than walking; the response (a frame period at least)
  // and the robot's stopping are never instant.
  read("approach_speed_m_s", separation.approach_speed_m_s, 1.6, 3.0,
       "1.6 .. 3 m/s (ISO 13855: 1.6 m/s walking, 2 m/s reaching)");
  read("response_s", separation.response_s, 0.01, 2.0, "0.01 .. 2 s");
  read("stopping_s", separation.stopping_s, 0.05, 5.0, "0.05 .. 5 s (measure it on the robot)");
  read("intrusion_m", separation.intrusion_m, 0.0, 2.0, "0 .. 2 m");
  return separation;
}

// protective_separation.reduced_speeds: up to four fractions of the top speed, descending.
std::vector<double> reduced_speeds_of(const Field& field) {
  constexpr std::size_t kMaxLevels = 4;  // each level is one more check per frame near someone
  if (!field.node.IsSequence() || field.node.size() > kMaxLevels) {
    throw_cell_error(field.at, field.path,
                     "expected a list of at most 4 speeds (fractions of the top speed), got " +
                         shown(field.node));
  }
  std::vector<double> speeds;
  for (std::size_t i = 0; i < field.node.size(); ++i) {
    const Field speed = element(field, i);
    speeds.push_back(bounded_of(speed, kMinReducedSpeed, kMaxReducedSpeed,
                                "0.05 .. 0.95 (a fraction of the top speed)"));
    if (i > 0 && speeds[i] >= speeds[i - 1]) {
      throw_cell_error(speed.at, speed.path,
                       "value " + speed.node.Scalar() + ", expected less than the speed before it");
    }
  }
  return speeds;
}

// A camera's source: exactly one of device, video, folder, gstreamer, url.
CameraSourceConfig camera_source_of(const Field& field,
                                    const std::filesystem::path& base_directory) {
  require_mapping(field);
  refuse_unknown_keys(field, {"device", "video", "folder", "gstreamer", "url"});
  if (field.node.size() != 1) {
    throw_cell_error(field.at, field.path,
                     "expected exactly one of device, video, folder, gstreamer, url");
  }
  using Kind = CameraSourceConfig::Kind;
  CameraSourceConfig source;
  source.at = field.at;
  if (field.node["device"]) {
    const Field device = require(field, "device");
    const int index = integer_of(device);
    if (index < 0 || index > 99'999) {
      throw_cell_error(device.at, device.path,
                       "value " + device.node.Scalar() + ", expected a device index 0 .. 99999");
    }
    source.kind = Kind::kDevice;
    source.spec = std::to_string(index);
  } else if (field.node["video"]) {
    source.kind = Kind::kVideoFile;
    source.spec = resolved(text_of(require(field, "video")), base_directory);
  } else if (field.node["folder"]) {
    source.kind = Kind::kImageFolder;
    source.spec = resolved(text_of(require(field, "folder")), base_directory);
  } else if (field.node["gstreamer"]) {
    const Field pipeline = require(field, "gstreamer");
    source.kind = Kind::kGstreamer;
    source.spec = text_of(pipeline);
    if (source.spec.find('!') == std::string::npos ||
        source.spec.find("appsink") == std::string::npos) {
      throw_cell_error(pipeline.at, pipeline.path,
                       "value '" + source.spec +
                           "', expected a GStreamer pipeline of elements joined by '!' ending in "
                           "an appsink");
    }
  } else {
    const Field url = require(field, "url");
    source.kind = Kind::kStream;
    source.spec = text_of(url);
    if (source.spec.find("://") == std::string::npos) {
      throw_cell_error(url.at, url.path,
                       "value '" + source.spec + "', expected a URL such as rtsp://host/stream");
    }
  }
  return source;
}

CameraConfig camera_of(const Field& field, const std::filesystem::path& base_directory) {
  require_mapping(field);
  refuse_unknown_keys(field, {"name", "calibration", "look_at", "source"});
  CameraConfig camera;
  camera.at = field.at;
  camera.name = text_of(require(field, "name"));
  if (field.node["source"]) {
    camera.source = camera_source_of(require(field, "source"), base_directory);
  }
  const bool has_calibration = static_cast<bool>(field.node["calibration"]);
  if (has_calibration == static_cast<bool>(field.node["look_at"])) {
    throw_cell_error(field.at, field.path,
                     "expected exactly one of 'calibration' (a file) and 'look_at' (a placement)");
  }
  if (has_calibration) {
    camera.calibration = resolved(text_of(require(field, "calibration")), base_directory);
    return camera;
  }
  const Field look_at = require(field, "look_at");
  require_mapping(look_at);
  refuse_unknown_keys(look_at, {"position_m", "target_m", "horizontal_fov_deg", "size_px"});
  LookAtConfig placement;
  placement.position_m = triple_of(require(look_at, "position_m"), "[x, y, z] in metres");
  placement.target_m = triple_of(require(look_at, "target_m"), "[x, y, z] in metres");
  placement.horizontal_fov_deg = number_of(require(look_at, "horizontal_fov_deg"));
  const Field size = require(look_at, "size_px");
  if (!size.node.IsSequence() || size.node.size() != 2) {
    throw_cell_error(size.at, size.path,
                     "expected [width, height] in pixels, got " + shown(size.node));
  }
  placement.width_px = integer_of(element(size, 0));
  placement.height_px = integer_of(element(size, 1));
  camera.look_at = placement;
  return camera;
}

// A top-level field the cell may leave out: `value` read by `read` (number_of, integer_of,
// text_of) and `at` its line when it is there, both untouched otherwise.
template <typename T, typename Read>
void read_optional(const Field& top, const char* key, Read read, std::optional<T>& value,
                   SourceLine& at) {
  if (!top.node[key]) return;
  const Field field = require(top, key);
  value = read(field);
  at = field.at;
}

}  // namespace

CellConfig parse_cell_yaml(std::string_view text, const std::string& source,
                           const std::filesystem::path& base_directory) {
  YAML::Node root;
  try {
    root = YAML::Load(std::string(text));
  } catch (const YAML::DeepRecursion& error) {
    throw_cell_error(SourceLine{source, error.mark.line >= 0 ? error.mark.line + 1 : 0}, "(file)",
                     "nested deeper than yaml-cpp's limit of 2000 levels, expected a cell file");
  } catch (const YAML::Exception& error) {
    throw_cell_error(SourceLine{source, error.mark.line >= 0 ? error.mark.line + 1 : 0}, "(file)",
                     "not valid YAML: " + error.msg);
  }
  const Field top{root, "", SourceLine{source, 1}};
  if (!root.IsMap()) {
    throw_cell_error(top.at, "(file)", "expected a mapping of cell fields, got " + shown(root));
  }
  refuse_unknown_keys(
      top, {"name", "m_max_m", "robot", "joints", "size_m", "cameras", "obstacles", "feature_grid",
            "blocked_cells", "camera_threshold", "occlusion_reach_cells", "envelope_max_move_m",
            "ball_radius_m", "robot_parts", "blind_spots", "entries", "entry_separation",
            "protective_separation"});

  CellConfig cell;
  cell.source = source;
  cell.name = text_of(require(top, "name"));
  const Field m_max = require(top, "m_max_m");
  cell.m_max_m = number_of(m_max);
  cell.m_max_at = m_max.at;
  if (root["robot"]) cell.robot = robot_of(require(top, "robot"), base_directory);

  const Field joints = require(top, "joints");
  cell.joints_at = joints.at;
  cell.joints = list_of<JointConfig>(joints, joint_of);

  if (root["size_m"]) {
    const Field size = require(top, "size_m");
    cell.size_m = triple_of(size, "[x, y, z] inside dimensions in metres");
    cell.size_at = size.at;
  }
  if (root["cameras"]) {
    const Field cameras = require(top, "cameras");
    cell.cameras_at = cameras.at;
    cell.cameras = list_of<CameraConfig>(
        cameras, [&](const Field& item) { return camera_of(item, base_directory); });
  }
  if (root["obstacles"]) {
    cell.obstacles = list_of<BoxObstacleConfig>(require(top, "obstacles"), obstacle_of);
  }
  if (root["feature_grid"]) {
    const Field grid = require(top, "feature_grid");
    require_mapping(grid);
    refuse_unknown_keys(grid, {"columns", "rows"});
    cell.feature_grid.at = grid.at;
    cell.feature_grid.columns = integer_of(require(grid, "columns"));
    cell.feature_grid.rows = integer_of(require(grid, "rows"));
  }
  if (root["blocked_cells"]) {
    const Field blocked = require(top, "blocked_cells");
    require_mapping(blocked);
    refuse_unknown_keys(blocked, {"weights", "threshold"});
    cell.blocked_cells.at = blocked.at;
    if (blocked.node["weights"]) {
      const Field weights = require(blocked, "weights");
      require_mapping(weights);
      refuse_unknown_keys(weights, {"average", "variance", "span", "contrast", "edge_count"});
      std::array<int, 5> values{0, 0, 0, 0, 0};
      const char* names[] = {"average", "variance", "span", "contrast", "edge_count"};
      for (std::size_t f = 0; f < values.size(); ++f) {
        if (weights.node[names[f]]) values[f] = integer_of(require(weights, names[f]));
      }
      cell.blocked_cells.weights = values;
    }
    if (blocked.node["threshold"]) {
      cell.blocked_cells.threshold = integer_of(require(blocked, "threshold"));
    }
  }
  read_optional(top, "camera_threshold", integer_of, cell.camera_threshold,
                cell.camera_threshold_at);
  read_optional(top, "occlusion_reach_cells", integer_of, cell.occlusion_reach_cells,
                cell.occlusion_reach_at);
  read_optional(top, "envelope_max_move_m", number_of, cell.envelope_max_move_m,
                cell.envelope_max_move_at);
  read_optional(top, "ball_radius_m", number_of, cell.ball_radius_m, cell.ball_radius_at);
  read_optional(top, "robot_parts", text_of, cell.robot_parts, cell.robot_parts_at);
  if (root["blind_spots"]) {
    const Field blind_spots = require(top, "blind_spots");
    const std::string value = text_of(blind_spots);
    if (value != "forbid" && value != "allow") {
      throw_cell_error(blind_spots.at, "blind_spots",
                       "value '" + value + "', expected forbid or allow");
    }
    cell.forbid_blind_spots = value == "forbid";
    cell.blind_spots_at = blind_spots.at;
  }
  if (root["entries"]) {
    const Field entries = require(top, "entries");
    cell.entries_at = entries.at;
    cell.entries = list_of<EntryConfig>(
        entries, [&](const Field& item) { return entry_of(item, cell.size_m); });
    if (cell.entries->empty()) {
      throw_cell_error(entries.at, "entries",
                       "an empty list, expected at least one entry (leave the field out when the "
                       "cell does not say where people come in)");
    }
  }
  if (root["entry_separation"]) {
    cell.entry_separation =
        separation_distance_of(require(top, "entry_separation"), SeparationDistanceConfig{});
  }
  // Unset: on, with the defaults; `off`: not checked.
  cell.protective_separation = default_protective_separation();
  if (root["protective_separation"]) {
    const Field separation = require(top, "protective_separation");
    cell.protective_separation_at = separation.at;
    if (separation.node.IsScalar()) {
      if (text_of(separation) != "off") {
        throw_cell_error(separation.at, "protective_separation",
                         "value '" + separation.node.Scalar() +
                             "', expected off or a mapping of approach_speed_m_s, response_s, "
                             "stopping_s, intrusion_m, reduced_speeds");
      }
      cell.protective_separation.reset();
    } else {
      cell.protective_separation =
          separation_distance_of(separation, default_protective_separation(), true);
      if (separation.node["reduced_speeds"]) {
        cell.protective_reduced_speeds = reduced_speeds_of(require(separation, "reduced_speeds"));
      }
      const double s = separation_distance_m(*cell.protective_separation);
      if (s > kMaxProtectiveSeparation_m) {
        std::ostringstream value;
        value << s;
        throw_cell_error(separation.at, "protective_separation",
                         "a separation distance of " + value.str() +
                             " m, expected at most 0.95 m (the robot would stop for anyone in "
                             "most of the cell)");
      }
    }
  }
  return cell;
}

CellConfig load_cell_file(const std::filesystem::path& path) {
  std::error_code error;
  if (std::filesystem::is_directory(path, error)) {
    throw_cell_error(SourceLine{path.string(), 0}, "(file)",
                     "is a directory, expected a YAML file");
  }
  // Larger is no cell (the default is 3 kB): refused before yaml-cpp reads it.
  constexpr std::uintmax_t kMaxCellBytes = std::uintmax_t{1} << 20;
  if (const auto bytes = std::filesystem::file_size(path, error); !error && bytes > kMaxCellBytes) {
    throw_cell_error(SourceLine{path.string(), 0}, "(file)",
                     std::to_string(bytes) + " bytes, expected at most " +
                         std::to_string(kMaxCellBytes) + " for a cell file");
  }
  std::ifstream file(path, std::ios::binary);
  if (!file) {
    throw_cell_error(SourceLine{path.string(), 0}, "(file)", "cannot be opened for reading");
  }
  std::ostringstream text;
  text << file.rdbuf();
  if (file.bad()) throw_cell_error(SourceLine{path.string(), 0}, "(file)", "read error");
  return parse_cell_yaml(text.str(), path.string(), path.parent_path());
}

CellConfig load_cell_file_or_default(const std::string& path) {
  return path.empty() ? default_cell() : load_cell_file(path);
}

}  // namespace safecell
