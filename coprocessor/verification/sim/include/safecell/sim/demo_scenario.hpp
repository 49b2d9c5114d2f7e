#pragma once
// The scenario of `safecell demo`: the robot swings every joint about a middle value, and a person
// walks in from one corner, past the robot within reach of its arm, and out to another. The demo
// and the link's integration test (which sends the demo's sequence of maps) share it.

#include <vector>

#include "safecell/cell/cell_model.hpp"
#include "safecell/cspace/cspace_grid.hpp"
#include "safecell/sim/human_walker.hpp"
#include "safecell/sim/simulated_cell.hpp"

namespace safecell {

inline constexpr double kDemoHumanEnters_s = 1.0;
inline constexpr double kDemoHumanSpeed_m_s = 1.0;

// The robot's configuration at time_s: every joint swings at its own period, inside the grid.
std::vector<double> demo_robot_at(const CspaceGrid& grid, double time_s);

// The person's path through the cell.
HumanWalker demo_person(const CellModel& cell);

// The scene at time_s: the robot, and the person while they are in the cell.
SimScene demo_scene(const CspaceGrid& grid, const HumanWalker& person, double time_s);

}  // namespace safecell
