#include "safecell/validation/configuration_strata.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace safecell {

const char* to_string(ConfigurationStratum stratum) {
  switch (stratum) {
    case ConfigurationStratum::kUniform:
      return "uniform";
    case ConfigurationStratum::kTowardsBody:
      return "towards_body";
    case ConfigurationStratum::kNearRobot:
      return "near_robot";
  }
  return "unknown";
}

std::vector<double> random_configuration(const CspaceGrid& grid, std::mt19937_64& rng) {
  std::vector<double> q(grid.joint_count());
  for (std::uint32_t j = 0; j < grid.joint_count(); ++j) {
    q[j] = std::uniform_real_distribution<double>(grid.joint(j).lo_rad, grid.joint(j).hi_rad)(rng);
  }
  return q;
}

std::vector<double> configuration_in_cell(const CspaceGrid& grid, CellIndex cell,
                                          std::mt19937_64& rng) {
  const auto coords = grid.coords_of(cell);
  if (!coords.ok()) throw std::out_of_range("cell " + std::to_string(cell) + " outside the grid");
  std::vector<double> q(grid.joint_count());
  for (std::uint32_t j = 0; j < grid.joint_count(); ++j) {
    const AngleInterval bounds = grid.cell_bounds(coords.value(), j).value();
    q[j] = std::uniform_real_distribution<double>(bounds.lo_rad, bounds.hi_rad)(rng);
  }
  return q;
}

CellIndex cell_of(const CspaceGrid& grid, const std::vector<double>& q) {
  if (q.size() != grid.joint_count()) {
    throw std::invalid_argument(std::to_string(q.size()) + " joint values for a grid of " +
                                std::to_string(grid.joint_count()) + " joints");
  }
  JointAngles angles;
  std::copy(q.begin(), q.end(), angles.rad);
  const auto cell = grid.cell_containing(angles);
  if (!cell.ok()) throw std::out_of_range("joint values outside the C-space grid");
  return cell.value();
}

std::vector<double> sample_configuration(ConfigurationStratum stratum, const CspaceGrid& grid,
                                         const SimScene& scene, std::size_t pick,
                                         std::mt19937_64& rng) {
  if (stratum == ConfigurationStratum::kNearRobot) {
    GridCoords near = grid.coords_of(cell_of(grid, scene.q)).value();
    for (std::uint32_t j = 0; j < grid.joint_count(); ++j) {
      const auto last = static_cast<int>(grid.cells_along(j)) - 1;
      const int offset = std::uniform_int_distribution<int>(-kNearRobotCells, kNearRobotCells)(rng);
      near.along[j] =
          static_cast<std::uint32_t>(std::clamp(static_cast<int>(near.along[j]) + offset, 0, last));
    }
    return configuration_in_cell(grid, grid.index_of(near).value(), rng);
  }
  std::vector<double> q = random_configuration(grid, rng);
  const std::size_t bodies = scene.humans.size() + scene.objects.size();
  if (stratum == ConfigurationStratum::kTowardsBody && bodies > 0) {
    const std::size_t body = pick % bodies;
    const Eigen::Vector2d target =
        body < scene.humans.size()
            ? scene.humans[body].position_m
            : Eigen::Vector2d(
                  scene.objects[body - scene.humans.size()].pose.translation().head<2>());
    q[0] = std::clamp(
        std::atan2(target.y(), target.x()) + std::uniform_real_distribution<double>(-0.3, 0.3)(rng),
        grid.joint(0).lo_rad, grid.joint(0).hi_rad);
  }
  return q;
}

}  // namespace safecell
