#include "safecell/sim/cell_simulation.hpp"

#include "safecell/cell/cell_error.hpp"

namespace safecell {

SimulatedCell simulate_cell(const CellModel& model, const SensorSettings& sensor,
                            RobotAppearance appearance) {
  if (!model.robot) {
    throw_cell_error(SourceLine{model.config.source, 0}, "robot",
                     "missing: the simulated cell needs the robot's URDF");
  }
  if (model.cameras.empty()) {
    throw_cell_error(SourceLine{model.config.source, 0}, "cameras",
                     "missing: the simulated cell needs at least one camera");
  }
  const auto& size = model.config.size_m;
  return SimulatedCell(*model.robot, model.cameras, Eigen::Vector3d(size[0], size[1], size[2]),
                       model.obstacles, sensor, appearance);
}

}  // namespace safecell
