#pragma once
// Reading a scene from the command line: joint values and humans, checked against the cell.
// Private to the CLI.

#include <string>
#include <vector>

#include "safecell/cell/cell_model.hpp"
#include "safecell/sim/human_figure.hpp"

namespace safecell {

// Throws InputError: "<option> '<value>': <expected>".
[[noreturn]] void bad_option(const std::string& option, const std::string& value,
                             const std::string& expected);

// "1,2.5,-3" -> {1, 2.5, -3}; anything else is a bad option.
std::vector<double> numbers_in(const std::string& option, const std::string& text);

// Joint values in radians from text in degrees (or radians), one per joint of the cell, each
// within the cell's range.
std::vector<double> joint_values_rad(const std::string& option, const std::string& text,
                                     bool in_degrees, const CellModel& model);

// "x,y" or "x,y,heading_deg": a human standing on the floor.
HumanPose human_of(const std::string& text);

}  // namespace safecell
