#include "safecell/lut_build/recorded_luts.hpp"

#include <stdexcept>
#include <string>

#include "safecell/base/fnv1a.hpp"
#include "safecell/envelope/static_obstacle_cells.hpp"
#include "safecell/errors/input_error.hpp"
#include "safecell/lut_build/lut_build_stages.hpp"

namespace safecell {

std::uint64_t recorded_lut_fingerprint(const CellModel& cell, const CspaceGrid& grid,
                                       const RecordingOptions& options) {
  Fnv1a64 hash;
  ModelLutOptions whole_robot;
  whole_robot.parts = PartSplit::kWholeRobot;  // a recording sees the whole robot
  hash.add_u64(model_lut_fingerprint(cell, grid, whole_robot));
  hash.add_u32(static_cast<std::uint32_t>(LutSource::kRecorded));
  hash.add_u32(static_cast<std::uint32_t>(options.key_stride));
  hash.add_u32(static_cast<std::uint32_t>(options.wrist_samples));
  hash.add_double(options.padding_m);
  return hash.value();
}

void check_recording_bounded(const RecordedSilhouettes& recording) {
  if (recording.unbounded_cameras().empty()) return;
  std::string names;
  for (const std::string& name : recording.unbounded_cameras()) {
    names += (names.empty() ? "" : ", ") + name;
  }
  throw InputError("recorded tables: camera(s) " + names +
                   " too close to the robot to bound a motion of " +
                   std::to_string(recording.motion_bound_m()) +
                   " m between keys in the image; use a smaller key stride or more "
                   "wrist samples");
}

LutSet build_recorded_luts(const CellModel& cell, const CspaceGrid& grid,
                           const RecordedSilhouettes& recording, unsigned threads,
                           const StagedProgress& progress) {
  if (!recording.recorded()) throw std::invalid_argument("recorded tables need a recording");
  check_recording_bounded(recording);
  std::vector<CellToPixelsTable> cell_tables = build_cell_tables(
      cell, grid.cell_count(), 1,
      [&recording](CellIndex cell_index, std::vector<FeatureMask>& masks) {
        for (std::size_t camera = 0; camera < masks.size(); ++camera) {
          recording.add_silhouette(cell_index, camera, masks[camera]);
        }
      },
      threads, progress);
  LutSet set;
  set.fingerprint = recorded_lut_fingerprint(cell, grid, recording.options());
  set.grid_fingerprint = grid.fingerprint();
  set.source = LutSource::kRecorded;
  set.columns = cell.feature_grid.columns();
  set.rows = cell.feature_grid.rows();
  // A recording sees the whole robot at once: one part.
  set.parts = robot_parts(*cell.robot, PartSplit::kWholeRobot);
  set.cameras = invert_cell_tables(cell, grid, 1, std::move(cell_tables), true, threads, progress);
  ModelLutOptions model_options;
  model_options.threads = threads;
  // Only its envelope (of whole cells) is used: no sub-cells drawn.
  const ModelSilhouettes model(cell, grid, model_options, CellDrawing::kWholeCells);
  set.static_cells =
      static_obstacle_cells(model.envelope(), cell.obstacles, threads, stage_progress(progress, 2));
  return set;
}

}  // namespace safecell
