#include "safecell/service/incident_folder.hpp"

#include <charconv>
#include <nlohmann/json.hpp>
#include <opencv2/imgcodecs.hpp>
#include <sstream>

#include "safecell/files/atomic_write.hpp"
#include "safecell/files/read_file.hpp"

namespace safecell {
namespace {

namespace fs = std::filesystem;
using Json = nlohmann::json;

// The JSON reader's checks: each names the file and the field.
class IncidentJson {
 public:
  explicit IncidentJson(fs::path file) : file_(std::move(file)) {}

  const Json& field(const Json& object, const std::string& key, const std::string& where) const {
    if (!object.is_object() || !object.contains(key)) fail(where + key, "is missing");
    return object.at(key);
  }
  double number(const Json& object, const std::string& key, const std::string& where) const {
    const Json& value = field(object, key, where);
    if (!value.is_number()) fail(where + key, "is " + value.dump() + ", expected a number");
    return value.get<double>();
  }
  std::uint64_t count(const Json& object, const std::string& key, const std::string& where) const {
    const Json& value = field(object, key, where);
    if (!value.is_number_unsigned()) {
      fail(where + key, "is " + value.dump() + ", expected a whole number");
    }
    return value.get<std::uint64_t>();
  }
  std::string text(const Json& object, const std::string& key, const std::string& where) const {
    const Json& value = field(object, key, where);
    if (!value.is_string()) fail(where + key, "is " + value.dump() + ", expected a string");
    return value.get<std::string>();
  }
  bool flag(const Json& object, const std::string& key, const std::string& where) const {
    const Json& value = field(object, key, where);
    if (!value.is_boolean()) fail(where + key, "is " + value.dump() + ", expected true or false");
    return value.get<bool>();
  }
  const Json& array(const Json& object, const std::string& key, const std::string& where) const {
    const Json& value = field(object, key, where);
    if (!value.is_array()) fail(where + key, "is not a list");
    return value;
  }
  std::vector<double> numbers(const Json& object, const std::string& key,
                              const std::string& where) const {
    std::vector<double> result;
    for (const Json& value : array(object, key, where)) {
      if (!value.is_number()) fail(where + key, "holds " + value.dump() + ", expected numbers");
      result.push_back(value.get<double>());
    }
    return result;
  }
  std::vector<std::string> texts(const Json& object, const std::string& key,
                                 const std::string& where) const {
    std::vector<std::string> result;
    for (const Json& value : array(object, key, where)) {
      if (!value.is_string()) fail(where + key, "holds " + value.dump() + ", expected strings");
      result.push_back(value.get<std::string>());
    }
    return result;
  }
  std::uint64_t fingerprint(const Json& object, const std::string& key,
                            const std::string& where) const {
    const std::string hex = text(object, key, where);
    std::uint64_t value = 0;
    const auto [end, error] = std::from_chars(hex.data(), hex.data() + hex.size(), value, 16);
    if (error != std::errc() || end != hex.data() + hex.size() || hex.empty()) {
      fail(where + key, "is \"" + hex + "\", expected a hexadecimal fingerprint");
    }
    return value;
  }
  [[noreturn]] void fail(const std::string& field, const std::string& problem) const {
    throw FileError(file_, "field '" + field + "' " + problem);
  }

 private:
  fs::path file_;
};

std::optional<CameraFault> camera_fault_named(const std::string& name) {
  for (int f = 0; f <= static_cast<int>(CameraFault::kOutOfSync); ++f) {
    if (name == to_string(static_cast<CameraFault>(f))) return static_cast<CameraFault>(f);
  }
  return std::nullopt;
}

IncidentView read_view(const IncidentJson& json, const Json& object, const std::string& where) {
  IncidentView view;
  const Json& exposure = json.field(object, "exposure_s", where);
  if (!exposure.is_null()) view.exposure_s = json.number(object, "exposure_s", where);
  const std::string fault = json.text(object, "fault", where);
  const std::optional<CameraFault> named = camera_fault_named(fault);
  if (!named) json.fail(where + "fault", "is \"" + fault + "\", not a camera fault's name");
  view.fault = *named;
  view.detail = json.text(object, "detail", where);
  return view;
}

IncidentCycle read_cycle(const IncidentJson& json, const Json& object, const std::string& where,
                         std::size_t cameras) {
  IncidentCycle cycle;
  cycle.index = json.count(object, "cycle", where);
  cycle.exposure_s = json.number(object, "exposure_s", where);
  cycle.pose_known = json.flag(object, "pose_known", where);
  cycle.q = json.numbers(object, "q_rad", where);
  if (cycle.pose_known && cycle.q.empty()) json.fail(where + "q_rad", "is empty, the pose known");
  cycle.known_views = static_cast<std::uint32_t>(json.count(object, "known_views", where));
  cycle.forbidden_cells = json.count(object, "forbidden_cells", where);
  cycle.all_forbidden = json.text(object, "all_forbidden", where);
  const Json& views = json.array(object, "views", where);
  if (views.size() != cameras) {
    json.fail(where + "views", "has " + std::to_string(views.size()) + " entries, expected " +
                                   std::to_string(cameras) + " (one per camera)");
  }
  for (std::size_t c = 0; c < views.size(); ++c) {
    cycle.views.push_back(read_view(json, views[c], where + "views[" + std::to_string(c) + "]."));
  }
  return cycle;
}

std::vector<double> numbers_in(const std::string& field, const fs::path& file, std::size_t line) {
  std::vector<double> values;
  std::istringstream in(field);
  std::string token;
  while (in >> token) {
    double value = 0.0;
    const auto [end, error] = std::from_chars(token.data(), token.data() + token.size(), value);
    if (error != std::errc() || end != token.data() + token.size()) {
      throw FileError(file, "line " + std::to_string(line) + ": \"" + token + "\" is not a number");
    }
    values.push_back(value);
  }
  return values;
}

std::vector<IncidentJointState> read_joints(const fs::path& file) {
  std::istringstream lines(read_file(file));
  std::string line;
  std::getline(lines, line);
  if (line.rfind("time_s,state,speed_scale,q_rad", 0) != 0) {
    throw FileError(file, "line 1 is \"" + line + "\", expected the header time_s,state,...");
  }
  std::vector<IncidentJointState> joints;
  for (std::size_t number = 2; std::getline(lines, line); ++number) {
    if (line.empty()) continue;
    std::vector<std::string> fields;
    std::istringstream columns(line);
    for (std::string field; std::getline(columns, field, ',');) fields.push_back(field);
    if (fields.size() < 4 || fields.size() > 5) {
      throw FileError(file, "line " + std::to_string(number) + " has " +
                                std::to_string(fields.size()) + " fields, expected 4 or 5");
    }
    IncidentJointState joint;
    const std::vector<double> time = numbers_in(fields[0], file, number);
    const std::vector<double> scale = numbers_in(fields[2], file, number);
    if (time.size() != 1 || scale.size() != 1) {
      throw FileError(file, "line " + std::to_string(number) + ": time or speed scale missing");
    }
    joint.time_s = time[0];
    joint.state = fields[1];
    joint.speed_scale = scale[0];
    joint.q = numbers_in(fields[3], file, number);
    if (fields.size() == 5) joint.velocity = numbers_in(fields[4], file, number);
    joints.push_back(std::move(joint));
  }
  return joints;
}

}  // namespace

fs::path incident_frame_file(const fs::path& folder, const std::string& camera,
                             std::uint64_t cycle) {
  return folder / "frames" / camera / (std::to_string(cycle) + ".png");
}

fs::path incident_map_file(const fs::path& folder, std::uint64_t cycle) {
  return folder / "maps" / (std::to_string(cycle) + ".bits");
}

Incident read_incident(const fs::path& folder) {
  const fs::path file = folder / "incident.json";
  const IncidentJson json(file);
  Json root;
  try {
    root = Json::parse(read_file(file, " (is this an incident folder?)"));
  } catch (const Json::parse_error& error) {
    throw FileError(file, std::string("is not JSON: ") + error.what());
  }
  const std::string format = json.text(root, "format", "");
  if (format != kIncidentFormat) {
    json.fail("format", "is \"" + format + "\", expected \"" + kIncidentFormat + "\"");
  }
  Incident incident;
  incident.causes = json.texts(root, "causes", "");
  incident.trigger_s = json.number(root, "trigger_s", "");
  const Json& setup = json.field(root, "setup", "");
  incident.setup.cell_file = json.text(setup, "cell_file", "setup.");
  incident.setup.grid_fingerprint = json.fingerprint(setup, "grid_fingerprint", "setup.");
  incident.setup.lut_fingerprint = json.fingerprint(setup, "lut_fingerprint", "setup.");
  incident.setup.sync_error_s = json.number(setup, "sync_error_s", "setup.");
  incident.cameras = json.texts(root, "cameras", "");
  if (incident.cameras.empty()) json.fail("cameras", "is empty");
  const Json& cycles = json.array(root, "cycles", "");
  for (std::size_t i = 0; i < cycles.size(); ++i) {
    incident.cycles.push_back(
        read_cycle(json, cycles[i], "cycles[" + std::to_string(i) + "].", incident.cameras.size()));
  }
  incident.setup.cell_text = read_file(folder / "cell.yaml");
  incident.joints = read_joints(folder / "joints.csv");
  return incident;
}

FrameSet incident_frame_set(const fs::path& folder, const Incident& incident,
                            const IncidentCycle& cycle) {
  FrameSet set;
  set.index = cycle.index;
  for (std::size_t c = 0; c < incident.cameras.size(); ++c) {
    const IncidentView& view = cycle.views.at(c);
    CameraFrame frame;
    frame.camera = incident.cameras[c];
    frame.exposure_s = view.exposure_s.value_or(cycle.exposure_s);
    frame.view = HealthReport{view.fault, view.detail};
    if (view.exposure_s) {
      const fs::path file = incident_frame_file(folder, frame.camera, cycle.index);
      frame.image = cv::imread(file.string(), cv::IMREAD_UNCHANGED);
      if (frame.image.empty() || frame.image.type() != CV_8UC1) {
        throw FileError(file, "missing or not an 8-bit gray image");
      }
    } else if (frame.view.healthy()) {
      frame.view = camera_fault_report(frame.camera, CameraFault::kStopped, "no frame recorded");
    }
    set.frames.push_back(std::move(frame));
  }
  return set;
}

CellSet read_incident_map(const fs::path& folder, const IncidentCycle& cycle,
                          std::uint32_t cell_count) {
  const fs::path file = incident_map_file(folder, cycle.index);
  const std::string bytes = read_file(file);
  CellSet map(cell_count);
  std::vector<std::uint64_t>& words = map.words();
  if (bytes.size() != words.size() * 8) {
    throw FileError(file, std::to_string(bytes.size()) + " bytes, expected " +
                              std::to_string(words.size() * 8) + " for " +
                              std::to_string(cell_count) + " cells");
  }
  for (std::size_t w = 0; w < words.size(); ++w) {
    std::uint64_t word = 0;
    for (int b = 7; b >= 0; --b) {
      word = (word << 8U) | static_cast<std::uint8_t>(bytes[w * 8 + static_cast<std::size_t>(b)]);
    }
    words[w] = word;
  }
  return map;
}

std::string fingerprint_hex(std::uint64_t fingerprint) {
  std::ostringstream text;
  text << std::hex << fingerprint;
  return text.str();
}

}  // namespace safecell
