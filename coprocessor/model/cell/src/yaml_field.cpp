#include "yaml_field.hpp"

#include <cmath>
#include <limits>
#include <map>
#include <sstream>

#include "safecell/cell/cell_error.hpp"

namespace safecell {

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

void refuse_repeated_keys(const Field& map) {
  // yaml-cpp keeps a repeated key and answers the first: the later line would be ignored.
  std::map<std::string, SourceLine> seen;
  for (const auto& entry : map.node) {
    const std::string key = entry.first.IsScalar() ? entry.first.Scalar() : shown(entry.first);
    const SourceLine at = line_of(entry.first, map.at.source);
    const auto [first, inserted] = seen.emplace(key, at);
    if (!inserted) {
      throw_cell_error(at, (map.path.empty() ? "" : map.path + ".") + key,
                       "given twice (first on line " + std::to_string(first->second.line) + ")");
    }
  }
}

void refuse_unknown_keys(const Field& map, std::initializer_list<std::string_view> known) {
  refuse_repeated_keys(map);
  for (const auto& entry : map.node) {
    const std::string key = entry.first.IsScalar() ? entry.first.Scalar() : shown(entry.first);
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

std::vector<double> numbers_of(const Field& field, std::size_t count, const std::string& expected) {
  if (!field.node.IsSequence() || field.node.size() != count) {
    throw_cell_error(field.at, field.path, "expected " + expected + ", got " + shown(field.node));
  }
  std::vector<double> values;
  for (std::size_t i = 0; i < count; ++i) {
    values.push_back(
        number_of(Field{field.node[i], field.path + "[" + std::to_string(i) + "]", field.at}));
  }
  return values;
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

Field element(const Field& list, std::size_t index) {
  const YAML::Node node = list.node[index];
  return Field{node, list.path + "[" + std::to_string(index) + "]", line_of(node, list.at.source)};
}

void require_mapping(const Field& field) {
  if (!field.node.IsMap()) {
    throw_cell_error(field.at, field.path, "expected a mapping, got " + shown(field.node));
  }
}

int integer_of(const Field& field) {
  const double value = number_of(field);
  if (!(std::abs(value) < 1e9) || value != std::floor(value)) {
    throw_cell_error(field.at, field.path, "expected a whole number, got " + shown(field.node));
  }
  return static_cast<int>(value);
}

}  // namespace safecell
