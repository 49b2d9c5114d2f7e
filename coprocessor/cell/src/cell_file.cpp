#include "safecell/cell/cell_file.hpp"

#include <yaml-cpp/yaml.h>

#include <fstream>
#include <initializer_list>
#include <limits>
#include <sstream>

#include "safecell/cell/cell_error.hpp"

namespace safecell {
namespace {

// A YAML node together with where it sits, for error messages.
struct Field {
  YAML::Node node;
  std::string path;  // "joints[2].l_m"
  SourceLine at;
};

SourceLine line_of(const YAML::Node& node, const std::string& source) {
  const YAML::Mark mark = node.Mark();
  return SourceLine{source, mark.line >= 0 ? mark.line + 1 : 0};
}

std::string shown(const YAML::Node& node) {
  if (node.IsScalar()) return "'" + node.Scalar() + "'";
  if (node.IsSequence()) return "a list";
  if (node.IsMap()) return "a mapping";
  return "nothing";
}

void refuse_unknown_keys(const Field& map, std::initializer_list<std::string_view> known) {
  for (const auto& entry : map.node) {
    const auto key = entry.first.as<std::string>();
    bool found = false;
    std::string expected;
    for (const auto name : known) {
      found = found || key == name;
      expected += (expected.empty() ? "" : ", ") + std::string(name);
    }
    if (!found) {
      throw_cell_error(line_of(entry.first, map.at.source),
                       (map.path.empty() ? "" : map.path + ".") + key,
                       "unknown field (expected one of: " + expected + ")");
    }
  }
}

Field require(const Field& map, const std::string& key) {
  const std::string path = map.path.empty() ? key : map.path + "." + key;
  const YAML::Node node = map.node[key];
  if (!node) throw_cell_error(map.at, path, "missing (required)");
  return Field{node, path, line_of(node, map.at.source)};
}

double number_of(const Field& field) {
  if (field.node.IsScalar()) {
    std::istringstream text(field.node.Scalar());
    double value = 0.0;
    text >> value;
    if (text && text.eof()) return value;
    // YAML spellings of special values; refused later as not finite, with a clear message.
    const std::string& s = field.node.Scalar();
    if (s == ".nan" || s == ".NaN" || s == ".NAN") return std::numeric_limits<double>::quiet_NaN();
    if (s == ".inf" || s == "+.inf" || s == ".Inf") return std::numeric_limits<double>::infinity();
    if (s == "-.inf" || s == "-.Inf") return -std::numeric_limits<double>::infinity();
  }
  throw_cell_error(field.at, field.path, "expected a number, got " + shown(field.node));
}

std::string text_of(const Field& field) {
  if (!field.node.IsScalar() || field.node.Scalar().empty()) {
    throw_cell_error(field.at, field.path, "expected a non-empty text, got " + shown(field.node));
  }
  return field.node.Scalar();
}

bool flag_of(const Field& field) {
  if (field.node.IsScalar()) {
    const std::string& s = field.node.Scalar();
    if (s == "true") return true;
    if (s == "false") return false;
  }
  throw_cell_error(field.at, field.path, "expected true or false, got " + shown(field.node));
}

JointConfig joint_of(const Field& field) {
  if (!field.node.IsMap()) {
    throw_cell_error(field.at, field.path, "expected a mapping, got " + shown(field.node));
  }
  refuse_unknown_keys(field, {"name", "range_deg", "l_m", "discretised"});
  JointConfig joint;
  joint.name = text_of(require(field, "name"));

  const Field range = require(field, "range_deg");
  if (!range.node.IsSequence() || range.node.size() != 2) {
    throw_cell_error(range.at, range.path,
                     "expected [lower, upper] in degrees, got " + shown(range.node));
  }
  joint.lo_deg = number_of(Field{range.node[0], range.path + "[0]", range.at});
  joint.hi_deg = number_of(Field{range.node[1], range.path + "[1]", range.at});
  joint.range_at = range.at;

  const Field lever = require(field, "l_m");
  joint.l_m = number_of(lever);
  joint.l_at = lever.at;

  if (field.node["discretised"]) joint.discretised = flag_of(require(field, "discretised"));
  return joint;
}

}  // namespace

CellConfig parse_cell_yaml(std::string_view text, const std::string& source) {
  YAML::Node root;
  try {
    root = YAML::Load(std::string(text));
  } catch (const YAML::Exception& error) {
    throw_cell_error(SourceLine{source, error.mark.line >= 0 ? error.mark.line + 1 : 0}, "(file)",
                     "not valid YAML: " + error.msg);
  }
  const Field top{root, "", SourceLine{source, 1}};
  if (!root.IsMap()) {
    throw_cell_error(top.at, "(file)", "expected a mapping of cell fields, got " + shown(root));
  }
  refuse_unknown_keys(top, {"name", "m_max_m", "joints"});

  CellConfig cell;
  cell.source = source;
  cell.name = text_of(require(top, "name"));
  const Field m_max = require(top, "m_max_m");
  cell.m_max_m = number_of(m_max);
  cell.m_max_at = m_max.at;

  const Field joints = require(top, "joints");
  if (!joints.node.IsSequence()) {
    throw_cell_error(joints.at, joints.path,
                     "expected a list of joints, got " + shown(joints.node));
  }
  cell.joints_at = joints.at;
  for (std::size_t i = 0; i < joints.node.size(); ++i) {
    const YAML::Node node = joints.node[i];
    cell.joints.push_back(
        joint_of(Field{node, "joints[" + std::to_string(i) + "]", line_of(node, source)}));
  }
  return cell;
}

CellConfig load_cell_file(const std::filesystem::path& path) {
  std::error_code error;
  if (std::filesystem::is_directory(path, error)) {
    throw_cell_error(SourceLine{path.string(), 0}, "(file)",
                     "is a directory, expected a YAML file");
  }
  std::ifstream file(path, std::ios::binary);
  if (!file) {
    throw_cell_error(SourceLine{path.string(), 0}, "(file)", "cannot be opened for reading");
  }
  std::ostringstream text;
  text << file.rdbuf();
  if (file.bad()) throw_cell_error(SourceLine{path.string(), 0}, "(file)", "read error");
  return parse_cell_yaml(text.str(), path.string());
}

}  // namespace safecell
