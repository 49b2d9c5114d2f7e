#pragma once
// LUT-1 from the robot model: for a C-space cell, the feature cells its envelope
// (cell_envelope.hpp) covers in each camera, as the union of its balls' image rectangles. The
// envelope's head, whose balls depend on few joint-cell combinations, is projected once per
// combination at construction and reused; the tail's balls are projected per cell, several at a
// time (ball_projection.hpp).
//
// Used twice: by the model-mode table build (every cell), and by robot removal at run time (one
// cell per cycle, a few tens of microseconds), so model-mode LUT files need not store LUT-1.
//
// Per robot part (robot_parts.hpp): the build takes each part's silhouette on its own, for the
// vote per part; robot removal takes the whole robot's, the union of the parts'.
//
// Sub-cells. A cell's envelope grows every ball by the sweeps of the cell's joints: one ball
// around a banana-shaped path, much wider than the path across it. With the cell's
// envelope_subdivision s > 1 each discretised joint's cell is cut into s equal sub-cells
// (CspaceGrid::subdivided), and the cell's silhouette is the union of its s^d sub-cells'
// envelopes, each swept over 1/s of the width: the same robot held (every configuration of the
// cell lies in one sub-cell), by balls that follow its path. envelope() stays the whole cell's.
// Per-cycle robot removal draws whole cells (CellDrawing::kWholeCells): 16 sub-cells cost about
// four times the cycle's fusion, and removal needs only a silhouette that holds the robot.
// The sub-cells overlap, so most of a sub-cell's balls land where earlier ones drew: with
// sub-cells the balls are drawn in groups (ball_groups.hpp), a group skipped whole when the mask
// holds its bound's rectangle already. The same silhouettes to the bit.

#include <Eigen/Geometry>
#include <cstdint>
#include <optional>
#include <vector>

#include "safecell/cell/cell_model.hpp"
#include "safecell/envelope/ball_groups.hpp"
#include "safecell/envelope/ball_projection.hpp"
#include "safecell/envelope/cell_envelope.hpp"
#include "safecell/robot/kinematics.hpp"
#include "safecell/robot/robot_parts.hpp"
#include "safecell/silhouettes/robot_silhouettes.hpp"

namespace safecell {

struct ModelLutOptions {
  // Size of the balls that cover the robot's surface; unset: the cell's (CellModel::ball_radius_m).
  std::optional<double> ball_radius_m;
  double padding_m = 0.02;  // added all round, for calibration and model error
  unsigned threads = 0;     // 0: one per hardware thread (table builds only)
  // The parts the cameras vote on; unset: the cell's (CellModel::robot_parts).
  std::optional<PartSplit> parts;
};

// The parts the tables of `cell` built with `options` vote on, and the size of their balls.
[[nodiscard]] inline PartSplit voting_parts(const CellModel& cell, const ModelLutOptions& options) {
  return options.parts.value_or(cell.robot_parts);
}
[[nodiscard]] inline double ball_radius_of(const CellModel& cell, const ModelLutOptions& options) {
  return options.ball_radius_m.value_or(cell.ball_radius_m);
}

// How a cell's silhouette is drawn: as the tables are (the cell file's sub-cells), or from the
// whole cell's envelope (wider; both hold the robot at every configuration of the cell).
enum class CellDrawing {
  kAsTheTables,  // the table builds and their checks: what the fingerprint names
  kWholeCells,   // robot removal once per cycle, where speed counts
};

class ModelSilhouettes final : public RobotSilhouettes {
 public:
  // Throws std::invalid_argument when the cell has no robot model or no camera, or for options
  // outside ball radius kMinBallRadius_m..kMaxBallRadius_m, padding 0..1 m.
  ModelSilhouettes(const CellModel& cell, const CspaceGrid& grid, const ModelLutOptions& options,
                   CellDrawing drawing = CellDrawing::kAsTheTables);

  [[nodiscard]] std::size_t camera_count() const override { return projections_.size(); }
  void add_silhouette(CellIndex cell, std::size_t camera, FeatureMask& mask) const override;
  // Every camera at once: the envelope is computed once.
  void add_silhouettes(CellIndex cell, std::vector<FeatureMask>& masks) const override;

  [[nodiscard]] const std::vector<RobotPart>& parts() const { return parts_; }
  // Every camera's silhouette of one part: masks[camera] |= it (masks.size() == camera_count(),
  // else std::invalid_argument; part < parts().size(), else std::out_of_range). Thread-safe.
  void add_part_silhouettes(CellIndex cell, std::size_t part, FeatureMask* masks) const;

  // The envelope of whole cells of the grid (static obstacles are tested against it).
  [[nodiscard]] const CellEnvelope& envelope() const { return envelope_; }
  // Sub-cells per discretised joint whose envelopes the silhouettes are drawn from (1: none).
  [[nodiscard]] std::uint32_t subdivision() const { return subdivision_; }
  [[nodiscard]] const FeatureGrid& feature_grid() const { return feature_grid_; }

 private:
  // masks[camera - first_camera] |= the silhouette of bodies `bodies`, for cameras
  // first_camera..end_camera-1: the union over the cell's sub-cells.
  void add_bodies(CellIndex cell, BodyRange bodies, std::size_t first_camera,
                  std::size_t end_camera, FeatureMask* masks) const;
  // The same for one cell of the drawn envelope's grid (a sub-cell).
  void add_sub_cell_bodies(const GridCoords& sub_cell, BodyRange bodies, std::size_t first_camera,
                           std::size_t end_camera, FeatureMask* masks) const;
  // The envelope the silhouettes are drawn from: of the sub-cells, or envelope_ without them.
  [[nodiscard]] const CellEnvelope& drawn() const {
    return sub_envelope_ ? *sub_envelope_ : envelope_;
  }
  // The balls of bodies first_body..end_body-1 (first_body >= 1) of a cell of drawn()'s grid:
  // those of its line's first cell (joint 0 at its first cell), made once per line and thread,
  // moved along the line (CellEnvelope::first_joint_motions). The builds go through the cells in
  // order, so most cells find their lines' balls made (a cell's sub-cells lie on s^(d-1) lines, a
  // thread keeps kLinesPerThread). The vectors are the calling thread's, valid until its next
  // call.
  // With sub-cells, the balls come in groups (ball_groups.hpp), made with the line's balls.
  struct LineTail {
    const std::vector<Ball>* balls;
    const std::vector<BallGroup>* groups;  // empty without sub-cells
  };
  LineTail tail_balls(const GridCoords& coords, std::size_t first_body, std::size_t end_body) const;

  std::vector<RobotPart> parts_;
  CspaceGrid grid_;
  FeatureGrid feature_grid_;
  CellEnvelope envelope_;
  std::uint32_t subdivision_ = 1;
  std::vector<std::uint32_t> discretised_joints_;  // the joints the sub-cells cut
  std::optional<CellEnvelope> sub_envelope_;       // on grid_.subdivided(subdivision_)
  std::vector<BallProjection> projections_;
  std::size_t cached_bodies_ = 0;
  std::vector<std::vector<std::vector<FeatureMask>>> cached_;  // [body][prefix][camera]
  std::vector<Eigen::Isometry3d> line_motions_;                // per cell of joint 0
  // Tells this object's lines from another's in a thread's store of them (tail_balls).
  std::uint64_t instance_ = 0;
};

// Checks the options as ModelSilhouettes does (for callers that validate early).
void check_model_lut_options(const CellModel& cell, const ModelLutOptions& options);

}  // namespace safecell
