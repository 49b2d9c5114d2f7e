#pragma once
// Reading typed fields from a YAML tree, with errors that name the file, line and field path.
// Private to the cell module.

#include <yaml-cpp/yaml.h>

#include <initializer_list>
#include <string>
#include <string_view>
#include <vector>

#include "safecell/cell/cell_config.hpp"

namespace safecell {

// A YAML node together with where it sits, for error messages.
struct Field {
  YAML::Node node;
  std::string path;  // "joints[2].l_m"
  SourceLine at;
};

SourceLine line_of(const YAML::Node& node, const std::string& source);
// How a node looks, for messages: 'text', a list, a mapping or nothing.
std::string shown(const YAML::Node& node);
// Throws CellError for a key of `map` that is given twice.
void refuse_repeated_keys(const Field& map);
// Throws CellError for a key of `map` that is not `known`, or that is given twice.
void refuse_unknown_keys(const Field& map, std::initializer_list<std::string_view> known);
// Precondition: map is a mapping. Throws CellError when the key is missing.
Field require(const Field& map, const std::string& key);
Field element(const Field& list, std::size_t index);
void require_mapping(const Field& field);
double number_of(const Field& field);
int integer_of(const Field& field);
std::vector<double> numbers_of(const Field& field, std::size_t count, const std::string& expected);
std::string text_of(const Field& field);
bool flag_of(const Field& field);

}  // namespace safecell
