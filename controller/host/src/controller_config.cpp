#include "safecell/controller/host/controller_config.hpp"

#include <arpa/inet.h>
#include <yaml-cpp/depthguard.h>
#include <yaml-cpp/yaml.h>

#include <charconv>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <initializer_list>
#include <map>
#include <sstream>
#include <string_view>

#include "safecell/cspace/cspace_grid.hpp"

namespace safecell {
namespace {

class Reader {
 public:
  explicit Reader(std::string source) : source_(std::move(source)) {}

  [[noreturn]] void fail(const YAML::Node& node, const std::string& field,
                         const std::string& problem) const {
    std::ostringstream message;
    message << source_;
    if (node.IsDefined() && node.Mark().line >= 0) message << ":" << node.Mark().line + 1;
    message << ": " << field << ": " << problem;
    throw ControllerConfigError(message.str());
  }

  std::string value_text(const YAML::Node& node) const {
    if (!node.IsDefined()) return "(missing)";
    if (node.IsScalar()) return "'" + node.Scalar() + "'";
    return "(a " + std::string(node.IsSequence() ? "list" : "map") + ")";
  }

  // Refuses a key of the map `node` that is given twice (yaml-cpp keeps both and answers the
  // first: the later line would be ignored) or that is not `known` (a misspelt key would leave
  // its default in place). `field` is the map's path ("" at the top).
  void refuse_unknown_keys(const YAML::Node& node, const std::string& field,
                           std::initializer_list<std::string_view> known) const {
    if (!node.IsDefined() || !node.IsMap()) return;
    std::map<std::string, int> lines;
    for (const auto& entry : node) {
      const std::string key = entry.first.IsScalar() ? entry.first.Scalar() : "(a list or map)";
      std::string path = field;
      if (!path.empty()) path += '.';
      path += key;
      const auto [first, added] = lines.emplace(key, entry.first.Mark().line + 1);
      if (!added) {
        fail(entry.first, path,
             "given twice (first on line " + std::to_string(first->second) + ")");
      }
      std::string expected;
      bool found = false;
      for (const std::string_view name : known) {
        found = found || key == name;
        expected += (expected.empty() ? "" : ", ") + std::string(name);
      }
      if (!found) fail(entry.first, path, "unknown key; expected one of " + expected);
    }
  }

  // parent[key], or an undefined node when the parent itself is missing (an optional section
  // left out: yaml-cpp throws on indexing an undefined node).
  // A missing key is an undefined node too, not yaml-cpp's "zombie" (whose IsSequence() and
  // the like throw InvalidNode: a file cut short ended the program with exit 70).
  static YAML::Node child(const YAML::Node& parent, const std::string& key) {
    if (!parent.IsDefined() || !parent.IsMap()) return YAML::Node(YAML::NodeType::Undefined);
    const YAML::Node node = parent[key];
    return node.IsDefined() ? node : YAML::Node(YAML::NodeType::Undefined);
  }

  YAML::Node map(const YAML::Node& parent, const std::string& key, const std::string& field,
                 bool required) const {
    const YAML::Node node = child(parent, key);
    if (!node.IsDefined()) {
      if (required) fail(parent, field, "missing; expected a map");
      return node;
    }
    if (!node.IsMap()) fail(node, field, "is " + value_text(node) + "; expected a map");
    return node;
  }

  double number(const YAML::Node& parent, const std::string& key, const std::string& field,
                double fallback, double lo, double hi, bool required = false) const {
    const YAML::Node node = child(parent, key);
    if (!node.IsDefined()) {
      if (required) fail(parent, field, "missing; expected a number");
      return fallback;
    }
    double value = 0.0;
    try {
      value = node.as<double>();
    } catch (const YAML::Exception&) {
      fail(node, field, "is " + value_text(node) + "; expected a number");
    }
    if (!std::isfinite(value) || value < lo || value > hi) {
      std::ostringstream expected;
      expected << "is " << value_text(node) << "; expected a number from " << lo << " to " << hi;
      fail(node, field, expected.str());
    }
    return value;
  }

  std::uint64_t unsigned_number(const YAML::Node& parent, const std::string& key,
                                const std::string& field, std::uint64_t fallback,
                                std::uint64_t hi) const {
    const YAML::Node node = child(parent, key);
    if (!node.IsDefined()) return fallback;
    std::uint64_t value = 0;
    try {
      value = node.as<std::uint64_t>();
    } catch (const YAML::Exception&) {
      fail(node, field, "is " + value_text(node) + "; expected a whole number >= 0");
    }
    if (value > hi)
      fail(node, field, "is " + value_text(node) + "; expected at most " + std::to_string(hi));
    return value;
  }

  std::string text(const YAML::Node& parent, const std::string& key,
                   const std::string& field) const {
    const YAML::Node node = child(parent, key);
    if (!node.IsScalar()) fail(node, field, "is " + value_text(node) + "; expected text");
    return node.Scalar();
  }

  bool boolean(const YAML::Node& parent, const std::string& key, const std::string& field,
               bool fallback) const {
    const YAML::Node node = child(parent, key);
    if (!node.IsDefined()) return fallback;
    try {
      return node.as<bool>();
    } catch (const YAML::Exception&) {
      fail(node, field, "is " + value_text(node) + "; expected true or false");
    }
  }

  StopCategory category(const YAML::Node& parent, const std::string& key, const std::string& field,
                        StopCategory fallback) const {
    const YAML::Node node = child(parent, key);
    if (!node.IsDefined()) return fallback;
    const std::string text = node.IsScalar() ? node.Scalar() : "";
    if (text == "category_1" || text == "1") return StopCategory::kCategory1;
    if (text == "category_2" || text == "2") return StopCategory::kCategory2;
    fail(node, field, "is " + value_text(node) + "; expected category_1 or category_2");
  }

  UdpAddress address(const YAML::Node& parent, const std::string& key, const std::string& field,
                     const UdpAddress& fallback) const {
    const YAML::Node node = child(parent, key);
    if (!node.IsDefined()) return fallback;
    const std::string text = node.IsScalar() ? node.Scalar() : "";
    const std::size_t colon = text.rfind(':');
    // The whole port must be digits: "1e999" or "42286abc" are no ports.
    unsigned port = 0;
    const char* port_begin = text.data() + (colon == std::string::npos ? 0 : colon + 1);
    const char* end = text.data() + text.size();
    const auto [stop, error] = std::from_chars(port_begin, end, port);
    in_addr ip{};
    if (colon == std::string::npos || error != std::errc{} || stop != end || port_begin == end ||
        port == 0 || port > 65535 ||
        ::inet_pton(AF_INET, text.substr(0, colon).c_str(), &ip) != 1) {
      fail(node, field,
           "is " + value_text(node) +
               "; expected IPV4:PORT with a port of 1..65535, e.g. "
               "127.0.0.1:47701");
    }
    return UdpAddress{text.substr(0, colon), static_cast<std::uint16_t>(port)};
  }

  std::vector<double> numbers(const YAML::Node& node, const std::string& field,
                              std::size_t count) const {
    if (!node.IsSequence() || node.size() != count) {
      fail(node, field,
           "is " + value_text(node) + "; expected a list of " + std::to_string(count) + " numbers");
    }
    std::vector<double> out;
    for (std::size_t i = 0; i < count; ++i) {
      try {
        out.push_back(node[i].as<double>());
      } catch (const YAML::Exception&) {
        fail(node[i], field + "[" + std::to_string(i) + "]",
             "is " + value_text(node[i]) + "; expected a number");
      }
      if (!std::isfinite(out.back())) fail(node[i], field, "holds a number that is not finite");
    }
    return out;
  }

 private:
  std::string source_;
};

void read_grid(const Reader& reader, const YAML::Node& root, ControllerConfig& config) {
  const YAML::Node grid = reader.map(root, "grid", "grid", true);
  reader.refuse_unknown_keys(grid, "grid", {"m_max_m", "joints"});
  config.grid.m_max_m = reader.number(grid, "m_max_m", "grid.m_max_m", 0.0, 1e-4, 10.0, true);
  const YAML::Node joints = Reader::child(grid, "joints");
  if (!joints.IsSequence() || joints.size() == 0 || joints.size() > kMaxJoints) {
    reader.fail(joints.IsDefined() ? joints : grid, "grid.joints",
                "expected a list of 1 to " + std::to_string(kMaxJoints) + " joints");
  }
  config.grid.joint_count = static_cast<std::uint32_t>(joints.size());
  for (std::size_t j = 0; j < joints.size(); ++j) {
    const std::string field = "grid.joints[" + std::to_string(j) + "]";
    reader.refuse_unknown_keys(joints[j], field, {"lo_rad", "hi_rad", "l_m", "discretised"});
    JointSpec& joint = config.grid.joints[j];
    joint.lo_rad = reader.number(joints[j], "lo_rad", field + ".lo_rad", 0.0, -1e3, 1e3, true);
    joint.hi_rad = reader.number(joints[j], "hi_rad", field + ".hi_rad", 0.0, -1e3, 1e3, true);
    joint.l_m = reader.number(joints[j], "l_m", field + ".l_m", 0.0, 0.0, 100.0, true);
    joint.discretised = reader.boolean(joints[j], "discretised", field + ".discretised", true);
  }
  const auto created = CspaceGrid::create(config.grid);
  if (!created.ok()) {
    const GridSpecError& error = created.error();
    reader.fail(grid, "grid (joint " + std::to_string(error.joint) + ")",
                std::string("refused: ") + to_string(error.field));
  }
}

void read_robot(const Reader& reader, const YAML::Node& root, ControllerConfig& config) {
  const YAML::Node robot = reader.map(root, "robot", "robot", true);
  reader.refuse_unknown_keys(robot, "robot", {"actuation_ms", "joints", "start_rad"});
  SimulatedRobotConfig& out = config.robot;
  out.joint_count = config.grid.joint_count;
  out.actuation_s =
      reader.number(robot, "actuation_ms", "robot.actuation_ms", 2.0, 0.0, 1000.0) * 1e-3;
  const YAML::Node joints = Reader::child(robot, "joints");
  if (!joints.IsSequence() || joints.size() != config.grid.joint_count) {
    reader.fail(
        joints.IsDefined() ? joints : robot, "robot.joints",
        "expected one entry per grid joint (" + std::to_string(config.grid.joint_count) + ")");
  }
  for (std::size_t j = 0; j < joints.size(); ++j) {
    const std::string field = "robot.joints[" + std::to_string(j) + "]";
    reader.refuse_unknown_keys(joints[j], field,
                               {"max_speed_rad_s", "accel_rad_s2", "decel_rad_s2"});
    SimulatedJoint& joint = out.joints[j];
    joint.lo_rad = config.grid.joints[j].lo_rad;
    joint.hi_rad = config.grid.joints[j].hi_rad;
    joint.max_speed_rad_s = reader.number(joints[j], "max_speed_rad_s", field + ".max_speed_rad_s",
                                          0.0, 1e-3, 100.0, true);
    joint.accel_rad_s2 =
        reader.number(joints[j], "accel_rad_s2", field + ".accel_rad_s2", 0.0, 1e-3, 1e4, true);
    joint.decel_rad_s2 =
        reader.number(joints[j], "decel_rad_s2", field + ".decel_rad_s2", 0.0, 1e-3, 1e4, true);
  }
  if (Reader::child(robot, "start_rad").IsDefined()) {
    const std::vector<double> start = reader.numbers(Reader::child(robot, "start_rad"),
                                                     "robot.start_rad", config.grid.joint_count);
    for (std::size_t j = 0; j < start.size(); ++j) {
      if (start[j] < config.grid.joints[j].lo_rad || start[j] > config.grid.joints[j].hi_rad) {
        reader.fail(Reader::child(robot, "start_rad"), "robot.start_rad[" + std::to_string(j) + "]",
                    "outside the joint's range in grid.joints");
      }
      out.start_rad[j] = start[j];
    }
  }
}

void read_rest(const Reader& reader, const YAML::Node& root, ControllerConfig& config) {
  const YAML::Node timing = reader.map(root, "timing", "timing", false);
  reader.refuse_unknown_keys(timing, "timing",
                             {"period_ms", "budget_ms", "watchdog_ms", "max_period_ms",
                              "max_data_age_ms", "max_clock_lead_ms"});
  ControllerTiming& t = config.timing;
  t.period_ms = reader.number(timing, "period_ms", "timing.period_ms", t.period_ms, 0.5, 100.0);
  t.budget_ms =
      reader.number(timing, "budget_ms", "timing.budget_ms", t.period_ms / 2, 0.01, t.period_ms);
  t.watchdog_ms = reader.number(timing, "watchdog_ms", "timing.watchdog_ms", t.watchdog_ms,
                                t.period_ms, 10000.0);
  t.max_period_ms = reader.number(timing, "max_period_ms", "timing.max_period_ms",
                                  1.5 * t.period_ms, t.period_ms, t.watchdog_ms);
  t.max_data_age_ms = reader.number(timing, "max_data_age_ms", "timing.max_data_age_ms",
                                    t.max_data_age_ms, 1.0, 10000.0);
  t.max_clock_lead_ms = reader.number(timing, "max_clock_lead_ms", "timing.max_clock_lead_ms",
                                      t.max_clock_lead_ms, 0.0, 1000.0);

  const YAML::Node safety = reader.map(root, "safety", "safety", false);
  reader.refuse_unknown_keys(
      safety, "safety",
      {"human_speed_m_s", "human_speed_reason", "min_healthy_cameras", "max_look_ahead_cells",
       "look_ahead_stop", "fault_stop", "test_only_look_ahead_off"});
  ControllerSafety& s = config.safety;
  // ISO 13855's walking speed is the floor, unless the file says why the cell's people are slower
  // (a reason of its own, kept beside the value).
  const bool reasoned = Reader::child(safety, "human_speed_reason").IsDefined();
  if (reasoned && reader.text(safety, "human_speed_reason", "safety.human_speed_reason").empty()) {
    reader.fail(Reader::child(safety, "human_speed_reason"), "safety.human_speed_reason",
                "is empty; expected why the cell's people move slower than 1.6 m/s");
  }
  s.human_speed_m_s = reader.number(safety, "human_speed_m_s", "safety.human_speed_m_s",
                                    s.human_speed_m_s, reasoned ? 0.1 : 1.6, 10.0);
  s.min_healthy_cameras = static_cast<std::uint32_t>(reader.unsigned_number(
      safety, "min_healthy_cameras", "safety.min_healthy_cameras", s.min_healthy_cameras, 64));
  if (s.min_healthy_cameras == 0) {
    reader.fail(Reader::child(safety, "min_healthy_cameras"), "safety.min_healthy_cameras",
                "is '0'; expected 1 to 64 (the fusion's camera threshold): with 0 the robot "
                "would move with every camera failed");
  }
  s.max_look_ahead_cells = static_cast<std::uint32_t>(reader.unsigned_number(
      safety, "max_look_ahead_cells", "safety.max_look_ahead_cells", s.max_look_ahead_cells, 1000));
  if (s.max_look_ahead_cells == 0)
    reader.fail(Reader::child(safety, "max_look_ahead_cells"), "safety.max_look_ahead_cells",
                "is '0'; expected at least 1");
  s.look_ahead_stop =
      reader.category(safety, "look_ahead_stop", "safety.look_ahead_stop", s.look_ahead_stop);
  s.fault_stop = reader.category(safety, "fault_stop", "safety.fault_stop", s.fault_stop);
  s.test_only_look_ahead_off =
      reader.boolean(safety, "test_only_look_ahead_off", "safety.test_only_look_ahead_off", false);

  const YAML::Node link = reader.map(root, "link", "link", false);
  reader.refuse_unknown_keys(link, "link",
                             {"listen", "coprocessor", "controller_id", "coprocessor_id",
                              "lut_fingerprint", "map_work_per_slice"});
  ControllerLinkSettings& l = config.link;
  l.listen = reader.address(link, "listen", "link.listen", l.listen);
  l.coprocessor = reader.address(link, "coprocessor", "link.coprocessor", l.coprocessor);
  l.controller_id = static_cast<std::uint32_t>(reader.unsigned_number(
      link, "controller_id", "link.controller_id", l.controller_id, 0xFFFFFFFFu));
  l.coprocessor_id = static_cast<std::uint32_t>(reader.unsigned_number(
      link, "coprocessor_id", "link.coprocessor_id", l.coprocessor_id, 0xFFFFFFFFu));
  l.lut_fingerprint =
      reader.unsigned_number(link, "lut_fingerprint", "link.lut_fingerprint", 0, ~std::uint64_t{0});
  l.map_work_per_slice = static_cast<std::uint32_t>(reader.number(
      link, "map_work_per_slice", "link.map_work_per_slice", l.map_work_per_slice, 1.0, 1e6));

  const YAML::Node task = reader.map(root, "task", "task", false);
  reader.refuse_unknown_keys(task, "task", {"goals_rad", "repeat", "motion"});
  if (task.IsDefined()) {
    const YAML::Node goals = Reader::child(task, "goals_rad");
    if (goals.IsDefined() && !goals.IsSequence())
      reader.fail(goals, "task.goals_rad", "expected a list of joint vectors");
    for (std::size_t g = 0; goals.IsDefined() && g < goals.size(); ++g) {
      const std::string field = "task.goals_rad[" + std::to_string(g) + "]";
      std::vector<double> goal = reader.numbers(goals[g], field, config.grid.joint_count);
      for (std::size_t j = 0; j < goal.size(); ++j) {
        if (goal[j] < config.grid.joints[j].lo_rad || goal[j] > config.grid.joints[j].hi_rad) {
          reader.fail(goals[g], field + "[" + std::to_string(j) + "]",
                      "outside the joint's range in grid.joints");
        }
      }
      config.task.goals_rad.push_back(std::move(goal));
    }
    config.task.repeat = reader.boolean(task, "repeat", "task.repeat", false);
    const YAML::Node motion = Reader::child(task, "motion");
    if (motion.IsDefined()) {
      const std::string text = motion.IsScalar() ? motion.Scalar() : "";
      if (text == "program") {
        config.task.motion = TaskMotion::kProgram;
      } else if (text != "gross_motion") {
        reader.fail(motion, "task.motion", "is '" + text + "'; expected gross_motion or program");
      }
    }
  }
  const YAML::Node store = reader.map(root, "map_store", "map_store", false);
  reader.refuse_unknown_keys(store, "map_store", {"pool_blocks"});
  config.pool_blocks = static_cast<std::uint32_t>(
      reader.unsigned_number(store, "pool_blocks", "map_store.pool_blocks", 0, 1u << 28));
}

}  // namespace

ControllerConfig parse_controller_config(const std::string& text, const std::string& source) {
  const Reader reader(source);
  YAML::Node root;
  try {
    root = YAML::Load(text);
  } catch (const YAML::DeepRecursion& error) {
    throw ControllerConfigError(source + ":" + std::to_string(error.mark.line + 1) +
                                ": nested deeper than yaml-cpp's limit of 2000 levels");
  } catch (const YAML::Exception& error) {
    throw ControllerConfigError(source + ":" + std::to_string(error.mark.line + 1) +
                                ": not valid YAML: " + error.msg);
  }
  if (!root.IsMap()) throw ControllerConfigError(source + ": expected a YAML map at the top");
  reader.refuse_unknown_keys(root, "",
                             {"grid", "robot", "timing", "safety", "link", "task", "map_store"});
  ControllerConfig config;
  config.source = source;
  read_grid(reader, root, config);
  read_robot(reader, root, config);
  read_rest(reader, root, config);
  return config;
}

ControllerConfig load_controller_config(const std::string& path) {
  // Larger is no controller file (the example is 5 kB): refused before yaml-cpp reads it.
  constexpr std::uintmax_t kMaxBytes = std::uintmax_t{1} << 20;
  std::error_code error;
  if (const auto bytes = std::filesystem::file_size(path, error); !error && bytes > kMaxBytes) {
    throw ControllerConfigError(path + ": " + std::to_string(bytes) + " bytes, expected at most " +
                                std::to_string(kMaxBytes) + " for a controller file");
  }
  std::ifstream file(path);
  if (!file) throw ControllerConfigError(path + ": cannot be read");
  std::ostringstream text;
  text << file.rdbuf();
  return parse_controller_config(text.str(), path);
}

}  // namespace safecell
