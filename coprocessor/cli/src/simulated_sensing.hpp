#pragma once
// The simulated cell's sensing as `safecell demo` and the end-to-end benchmark run it: the cell,
// its grid, the look-up tables (cached), the robot's silhouettes, the simulated cameras, the
// reference images (the median of frames of the empty cell) and the sensing pipeline over them.
// Private to the CLI. Fixed in place: the pipeline keeps references to the members before it.

#include <cstdint>
#include <ostream>
#include <string>

#include "lut_loading.hpp"
#include "safecell/cell/cell_model.hpp"
#include "safecell/pipeline/sensing_pipeline.hpp"
#include "safecell/silhouettes/model_silhouettes.hpp"
#include "safecell/sim/simulated_cell.hpp"
#include "safecell/sim_sources/simulated_reference.hpp"

namespace safecell {

// What a validation run changes of the cell file.
struct CellOverrides {
  int camera_threshold = 0;                // 0: the cell's
  bool protective_separation_off = false;  // the cell's protective separation turned off
};

struct SimulatedSensing {
  // cell_path: empty for the built-in default cell; lut_cache: empty for the default folder.
  // Messages (table building, reference images) go to `log`.
  SimulatedSensing(const std::string& cell_path, const std::string& lut_cache, std::uint64_t seed,
                   std::ostream& log, CellOverrides overrides = {});
  SimulatedSensing(const SimulatedSensing&) = delete;
  SimulatedSensing& operator=(const SimulatedSensing&) = delete;

  CellModel cell;
  CspaceGrid grid;
  CachedLuts luts;
  ModelSilhouettes silhouettes;  // robot removal's: whole cells (CellDrawing::kWholeCells)
  SimulatedCell sim;
  SimulatedReference reference;
  FusionSettings fusion;
  SensingPipeline pipeline;
};

}  // namespace safecell
