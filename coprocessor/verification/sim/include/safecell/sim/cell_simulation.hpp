#pragma once
// The simulated cell of a cell model: its robot, cameras, size and static boxes.

#include "safecell/cell/cell_model.hpp"
#include "safecell/sim/simulated_cell.hpp"

namespace safecell {

// Throws CellError when the cell names no robot or no camera.
SimulatedCell simulate_cell(const CellModel& model, const SensorSettings& sensor,
                            RobotAppearance appearance = RobotAppearance::kCollision);

}  // namespace safecell
