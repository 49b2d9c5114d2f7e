// How fast the simulated cell feeds its cameras: the target is the paper's set-up, 4 cameras of
// 704 x 576 at 30 Hz on one core, so one frame set must take well under 33 ms.
#include <benchmark/benchmark.h>

#include <cmath>

#include "safecell/bench/project_benchmarks.hpp"
#include "safecell/cell/cell_model.hpp"
#include "safecell/cell/default_cell.hpp"
#include "safecell/sim/cell_simulation.hpp"
#include "safecell/sim/human_walker.hpp"

namespace safecell {
namespace {

void render_four_default_cameras(benchmark::State& state) {
  SimulatedCell sim = simulate_cell(load_cell_model(default_cell()), SensorSettings{});
  const HumanWalker walker({{1.8, -1.8}, {0.8, -0.6}, {1.8, 1.0}});
  std::uint64_t frame = 0;
  while (state.KeepRunning()) {
    const double time_s = static_cast<double>(frame) / 30.0;
    const double phase = 0.7 * time_s;
    const SimScene scene{{0.6 * std::sin(phase), 0.3 + 0.2 * std::cos(phase), 0.8, 0.0, 0.5, 0.0},
                         {walker.pose_at(std::fmod(time_s, walker.arrival_time_s()))}};
    benchmark::DoNotOptimize(sim.render(scene, frame++, time_s));
  }
}

}  // namespace

void register_render_benchmarks() {
  register_benchmark("render_four_default_cameras", render_four_default_cameras,
                     benchmark::kMillisecond);
}

}  // namespace safecell
