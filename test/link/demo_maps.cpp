#include "demo_maps.hpp"

#include "model_fixture.hpp"
#include "safecell/pipeline/sensing_pipeline.hpp"
#include "safecell/pipeline/simulated_reference.hpp"
#include "safecell/sim/cell_simulation.hpp"
#include "safecell/sim/demo_scenario.hpp"

namespace safecell::test {

const DemoMaps& demo_maps() {
  static const DemoMaps maps = [] {
    constexpr double kFps = 30.0;
    constexpr int kCycles = 60;       // 2 s of the demo ...
    constexpr double kFirst_s = 0.5;  // ... from just before the person enters
    const CoarseTables tables;
    SimulatedCell sim = simulate_cell(tables.cell, SensorSettings{});
    const SimulatedReference reference = simulated_reference(sim, tables.cell, 5, 1);
    FusionSettings fusion;
    fusion.camera_threshold = tables.cell.camera_threshold;
    SensingPipeline pipeline(tables.cell, tables.grid, tables.luts, tables.silhouettes,
                             reference.frames, {}, fusion);
    const HumanWalker person = demo_person(tables.cell);
    DemoMaps out{tables.grid, {}};
    for (int cycle = 0; cycle < kCycles; ++cycle) {
      const double time_s = kFirst_s + cycle / kFps;
      const SimScene scene = demo_scene(tables.grid, person, time_s);
      const auto frames = sim.render(scene, static_cast<std::size_t>(cycle), time_s);
      out.maps.push_back(pipeline.process(frames, scene.q));
    }
    return out;
  }();
  return maps;
}

}  // namespace safecell::test
