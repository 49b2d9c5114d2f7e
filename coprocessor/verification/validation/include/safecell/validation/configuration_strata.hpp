#pragma once
// The robot configurations a validation scene is checked at, drawn on purpose from three strata
// (../shared/VALIDATION.md, "strata"), so that an average cannot hide the hard cases:
//   uniform         joint values uniform within the grid's ranges;
//   towards_body    uniform, with joint 1 turned towards one of the scene's humans or objects
//                   (within +-0.3 rad): the configurations that can reach them;
//   near_robot      inside a cell within +-2 cells of the robot's current cell along every
//                   discretised joint: the cells the controller checks next.

#include <array>
#include <cstddef>
#include <random>
#include <vector>

#include "safecell/cspace/cspace_grid.hpp"
#include "safecell/sim/simulated_cell.hpp"

namespace safecell {

enum class ConfigurationStratum : std::uint8_t { kUniform, kTowardsBody, kNearRobot };
inline constexpr std::size_t kConfigurationStrata = 3;
inline constexpr std::array<ConfigurationStratum, kConfigurationStrata> kAllConfigurationStrata = {
    ConfigurationStratum::kUniform, ConfigurationStratum::kTowardsBody,
    ConfigurationStratum::kNearRobot};

// "uniform", "towards_body", "near_robot".
[[nodiscard]] const char* to_string(ConfigurationStratum stratum);

// How far from the robot's cell the near_robot stratum reaches, in cells per discretised joint.
inline constexpr int kNearRobotCells = 2;

// Joint values drawn uniformly within the grid's ranges.
[[nodiscard]] std::vector<double> random_configuration(const CspaceGrid& grid,
                                                       std::mt19937_64& rng);

// Joint values uniformly inside `cell` (a joint that is not discretised anywhere in its range).
[[nodiscard]] std::vector<double> configuration_in_cell(const CspaceGrid& grid, CellIndex cell,
                                                        std::mt19937_64& rng);

// The cell holding joint values q (std::out_of_range when they lie outside the grid).
[[nodiscard]] CellIndex cell_of(const CspaceGrid& grid, const std::vector<double>& q);

// One configuration of the stratum for `scene` (the robot at scene.q; the bodies to turn
// towards: its humans and objects, the towards_body stratum falls back to uniform without any).
// `pick`: which body towards_body turns to (taken modulo their count).
[[nodiscard]] std::vector<double> sample_configuration(ConfigurationStratum stratum,
                                                       const CspaceGrid& grid,
                                                       const SimScene& scene, std::size_t pick,
                                                       std::mt19937_64& rng);

}  // namespace safecell
