#include "safecell/lut_build/model_luts.hpp"

#include "safecell/base/fnv1a.hpp"
#include "safecell/envelope/cell_envelope.hpp"
#include "safecell/envelope/static_obstacle_cells.hpp"
#include "safecell/lut_build/cell_table_builder.hpp"

namespace safecell {
namespace {

// How the tables are cut into runs and blocks: tables of another version decode to the same cells
// but may be slower to fuse, so a cached file of another version is built again. 2: boxes cover
// (may overlap) instead of partitioning; 3: boxes split by the trailing joints; 4: strips of line
// runs; 5: differences to the upper neighbour too.
constexpr std::uint32_t kTableCutVersion = 5;

void add_pose(Fnv1a64& hash, const Eigen::Isometry3d& pose) {
  for (int row = 0; row < 3; ++row) {
    for (int column = 0; column < 4; ++column) hash.add_double(pose.matrix()(row, column));
  }
}

void add_balls(Fnv1a64& hash, const std::vector<Ball>& balls) {
  hash.add_u64(balls.size());
  for (const auto& ball : balls) {
    hash.add_double(ball.centre_m.x());
    hash.add_double(ball.centre_m.y());
    hash.add_double(ball.centre_m.z());
    hash.add_double(ball.radius_m);
  }
}

}  // namespace

std::uint64_t model_lut_fingerprint(const CellModel& cell, const CspaceGrid& grid,
                                    const ModelLutOptions& options) {
  check_model_lut_options(cell, options);
  Fnv1a64 hash;
  hash.add_u64(grid.fingerprint());
  hash.add_u32(kTableCutVersion);
  hash.add_u32(CellEnvelope::kMethodVersion);
  hash.add_double(ball_radius_of(cell, options));
  hash.add_double(options.padding_m);
  // Whole cells hash as before sub-cells existed, so that their tables stay valid.
  if (cell.envelope_subdivision > 1) hash.add_u32(cell.envelope_subdivision);
  const RobotModel& robot = *cell.robot;
  for (const RobotPart& part : robot_parts(robot, voting_parts(cell, options))) {
    hash.add_u64(part.first_body);
    hash.add_u64(part.end_body);
  }
  for (const auto& joint : robot.joints) {
    add_pose(hash, joint.origin);
    hash.add_double(joint.axis.x());
    hash.add_double(joint.axis.y());
    hash.add_double(joint.axis.z());
    hash.add_u32(static_cast<std::uint32_t>(joint.type));
  }
  // The robot's geometry enters through its ball cover, which is a function of every shape.
  const RobotBalls balls = cover_with_balls(robot, ball_radius_of(cell, options));
  add_balls(hash, balls.base);
  for (const auto& link : balls.links) add_balls(hash, link);
  hash.add_u32(static_cast<std::uint32_t>(cell.feature_grid.columns()));
  hash.add_u32(static_cast<std::uint32_t>(cell.feature_grid.rows()));
  hash.add_u32(static_cast<std::uint32_t>(cell.feature_grid.cell_width_px()));
  hash.add_u32(static_cast<std::uint32_t>(cell.feature_grid.cell_height_px()));
  for (const auto& camera : cell.cameras) {
    for (const char c : camera.name()) hash.add_byte(static_cast<std::uint8_t>(c));
    hash.add_byte(0);
    const CameraIntrinsics& k = camera.intrinsics();
    for (const double value : {k.fx_px, k.fy_px, k.cx_px, k.cy_px, k.distortion.k1, k.distortion.k2,
                               k.distortion.p1, k.distortion.p2, k.distortion.k3}) {
      hash.add_double(value);
    }
    hash.add_u32(static_cast<std::uint32_t>(k.width_px));
    hash.add_u32(static_cast<std::uint32_t>(k.height_px));
    add_pose(hash, camera.cell_to_camera());
  }
  for (const auto& obstacle : cell.obstacles) {
    add_pose(hash, obstacle.pose);
    if (const auto* box = std::get_if<Box>(&obstacle.shape)) {
      hash.add_double(box->size_m.x());
      hash.add_double(box->size_m.y());
      hash.add_double(box->size_m.z());
    }
  }
  return hash.value();
}

LutSet build_model_luts(const CellModel& cell, const CspaceGrid& grid,
                        const ModelLutOptions& options, const StagedProgress& progress) {
  const ModelSilhouettes silhouettes(cell, grid, options);
  const std::size_t parts = silhouettes.parts().size();
  LutSet set;
  set.fingerprint = model_lut_fingerprint(cell, grid, options);
  set.grid_fingerprint = grid.fingerprint();
  set.source = LutSource::kModel;
  set.columns = cell.feature_grid.columns();
  set.rows = cell.feature_grid.rows();
  set.parts = silhouettes.parts();
  set.cameras.resize(cell.cameras.size());
  for (std::size_t camera = 0; camera < cell.cameras.size(); ++camera) {
    set.cameras[camera].camera = cell.cameras[camera].name();
  }
  // One part at a time: only that part's LUT-1 is held while its LUT-2 is built (LUT-1 of every
  // part at once took 17.6 GB on a 6 cm grid, and the build ran out of memory). Each part's
  // silhouettes cost what they did together: the balls of the parts before it come from the
  // cache of ModelSilhouettes.
  for (std::size_t part = 0; part < parts; ++part) {
    const StagedProgress part_progress = [&progress, part, parts](int stage, double fraction) {
      if (progress)
        progress(stage, (static_cast<double>(part) + fraction) / static_cast<double>(parts));
    };
    // Body b moves with joints 0..b-1 only (its envelope is swept by its own joints), so cells
    // that differ only in later joints' cells have the same silhouettes of the part: LUT-1 of the
    // first cells, one per combination of the joints that move its last body (that body's
    // prefixes), repeated (repeat_cells; joint 0 is the fastest in a cell's index).
    const auto leading = static_cast<std::uint32_t>(
        silhouettes.envelope().prefix_count(silhouettes.parts()[part].end_body - 1));
    std::vector<CellToPixelsTable> cell_tables = build_cell_tables(
        cell, leading, 1,
        [&silhouettes, part](CellIndex cell_index, std::vector<FeatureMask>& masks) {
          silhouettes.add_part_silhouettes(cell_index, part, masks.data());
        },
        options.threads, part_progress);
    for (CellToPixelsTable& table : cell_tables) {
      table = repeat_cells(table, grid.cell_count() / leading);
    }
    std::vector<CameraLuts> part_luts = invert_cell_tables(cell, grid, 1, std::move(cell_tables),
                                                           false, options.threads, part_progress);
    for (std::size_t camera = 0; camera < part_luts.size(); ++camera) {
      set.cameras[camera].parts.push_back(std::move(part_luts[camera].parts.front()));
    }
  }
  set.static_cells = static_obstacle_cells(silhouettes.envelope(), cell.obstacles, options.threads,
                                           stage_progress(progress, 2));
  return set;
}

}  // namespace safecell
