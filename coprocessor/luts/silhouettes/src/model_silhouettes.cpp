#include "safecell/silhouettes/model_silhouettes.hpp"

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <optional>
#include <stdexcept>
#include <string>

namespace safecell {
namespace {

// Numbers the ModelSilhouettes objects (ModelSilhouettes::instance_).
std::atomic<std::uint64_t> next_instance{1};

// The balls of one line's first cell for one range of bodies, as one thread last made them.
struct LineBalls {
  std::uint64_t instance = 0;  // 0: none yet
  CellIndex line_start = 0;    // the line's first cell
  std::size_t first_body = 0;
  std::size_t end_body = 0;
  std::vector<Ball> balls;
  std::vector<BallGroup> groups;  // of `balls`, when the cells are drawn in sub-cells
};

// A thread's lines: the build asks for one robot part at a time, and a cell's sub-cells lie on
// s^(d-1) lines (8 for s = 2 and 4 discretised joints); a caller that alternates parts finds each
// part's lines here too.
constexpr std::size_t kLinesPerThread = 32;

// Balls per group (ball_groups.hpp) where a cell is drawn as the union of its sub-cells. The
// sub-cells overlap: in the tables of 4 cm balls and 3 sub-cells per joint, 99.8 % of the balls'
// rectangles lie wholly in what earlier sub-cells drew, and 68 % of the groups of 8 (4 and 16:
// 84 and 49 %); the build of those tables took 106 s drawing every ball, 70 s with groups of 8.
constexpr std::size_t kBallsPerGroup = 8;

// The envelope of the cell's robot, after the checks (so that no argument touches a missing
// robot before they ran).
CellEnvelope checked_envelope(const CellModel& cell, const CspaceGrid& grid,
                              const ModelLutOptions& options) {
  check_model_lut_options(cell, options);
  std::vector<std::size_t> part_starts;
  for (const RobotPart& part : robot_parts(*cell.robot, voting_parts(cell, options))) {
    part_starts.push_back(part.first_body);
  }
  return CellEnvelope(*cell.robot, cover_with_balls(*cell.robot, ball_radius_of(cell, options)),
                      grid, options.padding_m, part_starts);
}

// The grid of the sub-cells the silhouettes are drawn from.
CspaceGrid sub_cell_grid(const CspaceGrid& grid, std::uint32_t subdivision) {
  const auto sub_cells = grid.subdivided(subdivision);
  if (!sub_cells.ok()) {
    throw std::invalid_argument("cutting every C-space cell into " + std::to_string(subdivision) +
                                " sub-cells per joint needs more than 2^32 - 1 cells");
  }
  return sub_cells.value();
}

}  // namespace

void check_model_lut_options(const CellModel& cell, const ModelLutOptions& options) {
  if (!cell.robot) {
    throw std::invalid_argument("cell '" + cell.config.name +
                                "' names no robot model; model-mode tables need one");
  }
  if (cell.cameras.empty()) {
    throw std::invalid_argument("cell '" + cell.config.name + "' has no camera");
  }
  const double ball_radius_m = ball_radius_of(cell, options);
  if (!is_ball_radius(ball_radius_m)) {
    throw std::invalid_argument("ball radius must be " + ball_radius_range() + ", got " +
                                std::to_string(ball_radius_m));
  }
  if (!std::isfinite(options.padding_m) || options.padding_m < 0.0 || options.padding_m > 1.0) {
    throw std::invalid_argument("padding must be 0..1 m, got " + std::to_string(options.padding_m));
  }
  const PartSplit split = voting_parts(cell, options);
  if (!is_part_split(split)) {
    throw std::invalid_argument("unknown robot part split " +
                                std::to_string(static_cast<std::uint32_t>(split)));
  }
}

ModelSilhouettes::ModelSilhouettes(const CellModel& cell, const CspaceGrid& grid,
                                   const ModelLutOptions& options, CellDrawing drawing)
    : grid_(grid),
      feature_grid_(cell.feature_grid),
      envelope_(checked_envelope(cell, grid, options)),
      subdivision_(drawing == CellDrawing::kWholeCells ? 1 : cell.envelope_subdivision) {
  if (subdivision_ < 1) throw std::invalid_argument("envelope subdivision 0");
  if (subdivision_ > 1) {
    sub_envelope_.emplace(checked_envelope(cell, sub_cell_grid(grid, subdivision_), options));
    for (std::uint32_t joint = 0; joint < grid.joint_count(); ++joint) {
      if (grid.joint(joint).discretised) discretised_joints_.push_back(joint);
    }
  }
  parts_ = robot_parts(*cell.robot, voting_parts(cell, options));
  projections_.reserve(cell.cameras.size());
  for (const auto& camera : cell.cameras) projections_.emplace_back(camera, cell.feature_grid);
  instance_ = next_instance.fetch_add(1);
  const CellEnvelope& envelope = drawn();
  envelope.first_joint_motions(line_motions_);
  cached_bodies_ = envelope.tail_body();  // the head, per prefix
  cached_.resize(cached_bodies_);
  std::vector<Ball> balls;
  for (std::size_t body = 0; body < cached_bodies_; ++body) {
    cached_[body].resize(envelope.prefix_count(body));
    for (std::size_t prefix = 0; prefix < cached_[body].size(); ++prefix) {
      balls.clear();
      envelope.append_body_balls(body, prefix, balls);
      cached_[body][prefix].assign(projections_.size(), FeatureMask(feature_grid_));
      for (std::size_t camera = 0; camera < projections_.size(); ++camera) {
        add_ball_rects(projections_[camera], balls, cached_[body][prefix][camera]);
      }
    }
  }
}

void ModelSilhouettes::add_silhouette(CellIndex cell, std::size_t camera, FeatureMask& mask) const {
  if (camera >= projections_.size()) {
    throw std::out_of_range("camera " + std::to_string(camera) + " of " +
                            std::to_string(projections_.size()));
  }
  add_bodies(cell, {}, camera, camera + 1, &mask);
}

void ModelSilhouettes::add_silhouettes(CellIndex cell, std::vector<FeatureMask>& masks) const {
  if (masks.size() != projections_.size()) {
    throw std::invalid_argument(std::to_string(masks.size()) + " masks for " +
                                std::to_string(projections_.size()) + " cameras");
  }
  add_bodies(cell, {}, 0, projections_.size(), masks.data());
}

void ModelSilhouettes::add_part_silhouettes(CellIndex cell, std::size_t part,
                                            FeatureMask* masks) const {
  const RobotPart& robot_part = parts_.at(part);
  add_bodies(cell, {robot_part.first_body, robot_part.end_body}, 0, projections_.size(), masks);
}

void ModelSilhouettes::add_bodies(CellIndex cell, BodyRange bodies, std::size_t first_camera,
                                  std::size_t end_camera, FeatureMask* masks) const {
  const auto coords = grid_.coords_of(cell);
  if (!coords.ok()) throw std::out_of_range("cell " + std::to_string(cell) + " outside the grid");
  if (subdivision_ == 1) {
    add_sub_cell_bodies(coords.value(), bodies, first_camera, end_camera, masks);
    return;
  }
  // Body b moves with joints 0..b-1 only: the sub-cells of a later joint draw these bodies the
  // same, so they are cut along the joints that move them, and along the others the first
  // sub-cell stands for all (the same balls to the bit: the envelope's sweeps of a body are by
  // its own joints).
  const std::size_t end_body = std::min(bodies.end, drawn().body_count());
  std::size_t cut_joints = 0;
  while (cut_joints < discretised_joints_.size() &&
         discretised_joints_[cut_joints] + 1 < end_body) {
    ++cut_joints;
  }
  std::size_t sub_cells = 1;
  for (std::size_t joint = 0; joint < cut_joints; ++joint) sub_cells *= subdivision_;
  GridCoords sub_cell = coords.value();
  for (const std::uint32_t joint : discretised_joints_) {
    sub_cell.along[joint] = coords.value().along[joint] * subdivision_;
  }
  // Joint 0 fastest, so that neighbouring sub-cells share a line (tail_balls).
  for (std::size_t index = 0; index < sub_cells; ++index) {
    std::size_t rest = index;
    for (std::size_t cut = 0; cut < cut_joints; ++cut) {
      const std::uint32_t joint = discretised_joints_[cut];
      sub_cell.along[joint] = coords.value().along[joint] * subdivision_ +
                              static_cast<std::uint32_t>(rest % subdivision_);
      rest /= subdivision_;
    }
    add_sub_cell_bodies(sub_cell, bodies, first_camera, end_camera, masks);
  }
}

void ModelSilhouettes::add_sub_cell_bodies(const GridCoords& sub_cell, BodyRange bodies,
                                           std::size_t first_camera, std::size_t end_camera,
                                           FeatureMask* masks) const {
  const CellEnvelope& envelope = drawn();
  const std::size_t end_body = std::min(bodies.end, envelope.body_count());
  const std::size_t end_cached = std::min(end_body, cached_bodies_);
  const LineTail tail = tail_balls(sub_cell, std::max(bodies.first, cached_bodies_), end_body);
  for (std::size_t camera = first_camera; camera < end_camera; ++camera) {
    FeatureMask& mask = masks[camera - first_camera];
    for (std::size_t body = bodies.first; body < end_cached; ++body) {
      mask |= cached_[body][envelope.prefix_of(sub_cell, body)][camera];
    }
    if (subdivision_ > 1) {
      add_grouped_ball_rects(projections_[camera], *tail.balls, *tail.groups, mask);
    } else {
      add_ball_rects(projections_[camera], *tail.balls, mask);
    }
  }
}

ModelSilhouettes::LineTail ModelSilhouettes::tail_balls(const GridCoords& coords,
                                                        std::size_t first_body,
                                                        std::size_t end_body) const {
  thread_local std::array<LineBalls, kLinesPerThread> lines;
  thread_local std::size_t next_replaced = 0;
  thread_local std::vector<Ball> moved;
  thread_local std::vector<BallGroup> moved_groups;
  GridCoords line_start = coords;
  line_start.along[0] = 0;
  const CellEnvelope& envelope = drawn();
  const CellIndex start = envelope.grid().index_of(line_start).value();
  const auto same_line = [&](const LineBalls& line) {
    return line.instance == instance_ && line.line_start == start &&
           line.first_body == first_body && line.end_body == end_body;
  };
  auto found = std::find_if(lines.begin(), lines.end(), same_line);
  if (found == lines.end()) {
    found = lines.begin() + static_cast<std::ptrdiff_t>(next_replaced);
    next_replaced = (next_replaced + 1) % kLinesPerThread;
    found->instance = 0;  // no line's, until it is made whole (balls_of_bodies may throw)
    envelope.balls_of_bodies(line_start, first_body, end_body, found->balls);
    found->groups.clear();
    if (subdivision_ > 1) group_balls(found->balls, kBallsPerGroup, found->groups);
    found->instance = instance_;
    found->line_start = start;
    found->first_body = first_body;
    found->end_body = end_body;
  }
  const Eigen::Isometry3d& motion = line_motions_[coords.along[0]];
  moved.clear();
  for (const Ball& ball : found->balls) {
    moved.push_back(CellEnvelope::moved_ball(motion, ball));
  }
  // A bound moved as its balls are still holds them (the motion is rigid; moved_ball grows both
  // by the same margin).
  moved_groups.clear();
  for (const BallGroup& group : found->groups) {
    moved_groups.push_back({CellEnvelope::moved_ball(motion, group.bound), group.first, group.end});
  }
  return {&moved, &moved_groups};
}

}  // namespace safecell
