#include "scene_options.hpp"

#include <cmath>
#include <numbers>
#include <sstream>
#include <stdexcept>

#include "safecell/cli/text_table.hpp"
#include "safecell/errors/input_error.hpp"

namespace safecell {

namespace {

constexpr double kRadPerDeg = std::numbers::pi / 180.0;

}  // namespace

[[noreturn]] void bad_option(const std::string& option, const std::string& value,
                             const std::string& expected) {
  throw InputError(option + " '" + value + "': " + expected);
}

std::vector<double> numbers_in(const std::string& option, const std::string& text) {
  std::vector<double> values;
  std::stringstream stream(text);
  std::string item;
  while (std::getline(stream, item, ',')) {
    std::size_t used = 0;
    double value = 0.0;
    try {
      value = std::stod(item, &used);
    } catch (const std::exception&) {
      used = 0;
    }
    if (used == 0 || used != item.size() || !std::isfinite(value)) {
      bad_option(option, text, "expected comma-separated numbers, '" + item + "' is not one");
    }
    values.push_back(value);
  }
  return values;
}

std::vector<double> joint_values_rad(const std::string& option, const std::string& text,
                                     bool in_degrees, const CellModel& model) {
  std::vector<double> q = numbers_in(option, text);
  const auto& joints = model.config.joints;
  if (q.size() != joints.size()) {
    bad_option(
        option, text,
        std::to_string(joints.size()) + " joint values expected, got " + std::to_string(q.size()));
  }
  for (std::size_t j = 0; j < q.size(); ++j) {
    const double deg = in_degrees ? q[j] : q[j] / kRadPerDeg;
    const auto& range = joints[j].range_deg.value();
    if (deg < range[0] || deg > range[1]) {
      bad_option(option, text,
                 joints[j].name + " = " + fixed(deg, 2) + " deg lies outside the cell's range [" +
                     fixed(range[0], 2) + ", " + fixed(range[1], 2) + "] deg");
    }
    q[j] = deg * kRadPerDeg;
  }
  return q;
}

HumanPose human_of(const std::string& text) {
  const auto values = numbers_in("--human", text);
  if (values.size() != 2 && values.size() != 3) {
    bad_option("--human", text, "expected x,y or x,y,heading_deg (metres, degrees)");
  }
  HumanPose pose;
  pose.position_m = Eigen::Vector2d(values[0], values[1]);
  pose.heading_rad = values.size() == 3 ? values[2] * kRadPerDeg : 0.0;
  return pose;
}

}  // namespace safecell
