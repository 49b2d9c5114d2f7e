#include "safecell/cell/cell_grid.hpp"

#include <sstream>

#include "safecell/base/freestanding_math.hpp"
#include "safecell/cell/cell_error.hpp"

namespace safecell {
namespace {

double radians(double degrees) { return degrees * kPi / 180.0; }

std::string number(double value) {
  std::ostringstream text;
  text << value;
  return text.str();
}

[[noreturn]] void throw_refusal(const CellConfig& cell, const GridSpecError& error) {
  const auto joint_index = error.joint;
  const std::string joint_path = "joints[" + std::to_string(joint_index) + "]";
  switch (error.field) {
    case GridField::kJointCount:
      throw_cell_error(cell.joints_at, "joints",
                       std::to_string(cell.joints.size()) + " joints given, expected 1 to " +
                           std::to_string(kMaxJoints));
    case GridField::kMaxMove:
      throw_cell_error(cell.m_max_at, "m_max_m",
                       "value " + number(cell.m_max_m) + ", expected a distance above 0 m");
    case GridField::kRange: {
      const JointConfig& joint = cell.joints.at(joint_index);
      throw_cell_error(joint.range_at, joint_path + ".range_deg",
                       "value [" + number(joint.range_deg.value()[0]) + ", " +
                           number(joint.range_deg.value()[1]) +
                           "], expected finite limits with lower < upper");
    }
    case GridField::kLeverArm: {
      const JointConfig& joint = cell.joints.at(joint_index);
      throw_cell_error(
          joint.l_at, joint_path + ".l_m",
          "value " + number(joint.l_m.value()) +
              (joint.discretised
                   ? ", expected at least m_max_m / 2 = " + number(cell.m_max_m / 2.0) +
                         " m for a discretised joint (one that moves the robot "
                         "less is swept: discretised: false)"
                   : ", expected a finite distance >= 0 m"));
    }
    case GridField::kCellCount:
      throw_cell_error(cell.joints.at(joint_index).l_at, joint_path,
                       "the grid would need more than 2^32 - 1 cells; raise m_max_m or "
                       "discretise fewer joints");
  }
  throw_cell_error(SourceLine{cell.source, 0}, "(grid)", to_string(error.status));
}

}  // namespace

GridSpec grid_spec_of(const CellConfig& cell) {
  GridSpec spec;
  spec.m_max_m = cell.m_max_m;
  spec.joint_count = static_cast<std::uint32_t>(cell.joints.size());
  const std::size_t copied = cell.joints.size() < kMaxJoints ? cell.joints.size() : kMaxJoints;
  for (std::size_t j = 0; j < copied; ++j) {
    const JointConfig& joint = cell.joints[j];
    spec.joints[j] =
        JointSpec{radians(joint.range_deg.value()[0]), radians(joint.range_deg.value()[1]),
                  joint.l_m.value(), joint.discretised};
  }
  return spec;
}

CspaceGrid make_grid(const CellConfig& cell) {
  auto grid = CspaceGrid::create(grid_spec_of(cell));
  if (!grid.ok()) throw_refusal(cell, grid.error());
  return grid.value();
}

}  // namespace safecell
