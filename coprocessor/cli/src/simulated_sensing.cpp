#include "simulated_sensing.hpp"

#include "safecell/cell/cell_file.hpp"
#include "safecell/cell/cell_grid.hpp"
#include "safecell/pipeline/cell_fusion_settings.hpp"
#include "safecell/sim/cell_simulation.hpp"

namespace safecell {
namespace {

constexpr std::size_t kReferenceFrames = 9;

SimulatedCell simulated_cameras(const CellModel& cell, std::uint64_t seed) {
  SensorSettings sensor;
  sensor.seed = seed;
  return simulate_cell(cell, sensor);
}

SimulatedReference reference_images(SimulatedCell& sim, const CellModel& cell, std::uint64_t seed,
                                    std::ostream& log) {
  log << "reference images: median of " << kReferenceFrames << " frames of the empty cell\n";
  return simulated_reference(sim, cell, kReferenceFrames, seed);
}

CellModel cell_with(const std::string& cell_path, const CellOverrides& overrides) {
  CellConfig config = load_cell_file_or_default(cell_path);
  if (overrides.camera_threshold > 0) config.camera_threshold = overrides.camera_threshold;
  if (overrides.protective_separation_off) config.protective_separation.reset();
  return load_cell_model(std::move(config));
}

}  // namespace

SimulatedSensing::SimulatedSensing(const std::string& cell_path, const std::string& lut_cache,
                                   std::uint64_t seed, std::ostream& log, CellOverrides overrides)
    : cell(cell_with(cell_path, overrides)),
      grid(make_grid(cell.config)),
      luts(cell_luts(cell, grid, ModelLutOptions{}, lut_cache, log)),
      silhouettes(cell, grid, ModelLutOptions{}, CellDrawing::kWholeCells),
      sim(simulated_cameras(cell, seed)),
      reference(reference_images(sim, cell, seed, log)),
      fusion(cell_fusion_settings(cell)),
      pipeline(cell, grid, luts.set, silhouettes, reference.frames, {}, fusion) {}

}  // namespace safecell
