#include "safecell/validation/demo_maps.hpp"

#include "safecell/pipeline/cell_fusion_settings.hpp"
#include "safecell/pipeline/sensing_pipeline.hpp"
#include "safecell/sim/cell_simulation.hpp"
#include "safecell/sim/demo_scenario.hpp"
#include "safecell/sim_sources/simulated_reference.hpp"

namespace safecell {

std::vector<CellSet> demo_map_sequence(const CellModel& cell, const CspaceGrid& grid,
                                       const LutSet& luts, const RobotSilhouettes& silhouettes,
                                       double first_s, int cycles, double fps) {
  SimulatedCell sim = simulate_cell(cell, SensorSettings{});
  const SimulatedReference reference = simulated_reference(sim, cell, 9, 1);
  const FusionSettings fusion = cell_fusion_settings(cell);
  SensingPipeline pipeline(cell, grid, luts, silhouettes, reference.frames, {}, fusion);
  const HumanWalker person = demo_person(cell);
  std::vector<CellSet> maps;
  for (int cycle = 0; cycle < cycles; ++cycle) {
    const double time_s = first_s + cycle / fps;
    const SimScene scene = demo_scene(grid, person, time_s);
    maps.push_back(
        pipeline.process(sim.render(scene, static_cast<std::size_t>(cycle), time_s), scene.q));
  }
  return maps;
}

}  // namespace safecell
