#include "safecell/envelope/cell_envelope.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <span>
#include <stdexcept>
#include <string>
#include <utility>

#include "safecell/geometry/point_transform.hpp"
#include "safecell/robot/kinematics.hpp"

namespace safecell {
namespace {

// How one joint moves the balls after it within the cell: about (or along) `direction` through
// `point`, by up to half_width either way.
struct JointAxis {
  Eigen::Vector3d point;      // on the axis, base frame
  Eigen::Vector3d direction;  // unit, base frame
  bool prismatic = false;
  double half_width = 0.0;        // rad (m for a prismatic joint)
  double chord_per_radius = 0.0;  // 2 sin(min(half_width, pi) / 2)
};

// The point of the joint's axis closest to `point` (base frame).
Eigen::Vector3d foot_on_axis(const JointAxis& axis, const Eigen::Vector3d& point) {
  return axis.point + (point - axis.point).dot(axis.direction) * axis.direction;
}

// Grows `ball` (base frame) so that it holds the ball turned or shifted by the joint.
void sweep(const JointAxis& axis, Ball& ball) {
  if (axis.prismatic) {
    ball.radius_m += axis.half_width;
    return;
  }
  const Eigen::Vector3d foot = foot_on_axis(axis, ball.centre_m);
  const double r = (ball.centre_m - foot).norm();
  const double chord = axis.chord_per_radius * r;
  if (r < chord) {
    ball.centre_m = foot;
    ball.radius_m += r;
  } else {
    ball.radius_m += chord;
  }
}

// Balls inside another by less than this are kept (rounding must not drop a sliver of the robot).
constexpr double kCoverMargin_m = 1e-9;

// The balls without those that lie inside another: the union is the same.
std::vector<Ball> without_covered_balls(std::vector<Ball> balls) {
  // Largest first: a ball inside a dropped ball is inside the kept ball that holds that one.
  std::stable_sort(balls.begin(), balls.end(),
                   [](const Ball& a, const Ball& b) { return a.radius_m > b.radius_m; });
  std::vector<Ball> kept;
  for (const Ball& ball : balls) {
    const bool covered = std::any_of(kept.begin(), kept.end(), [&ball](const Ball& big) {
      return (ball.centre_m - big.centre_m).norm() + ball.radius_m <= big.radius_m - kCoverMargin_m;
    });
    if (!covered) kept.push_back(ball);
  }
  return kept;
}

// The corners of the bounding box of the balls' centres (balls not empty).
std::pair<Eigen::Vector3d, Eigen::Vector3d> centres_box(std::span<const Ball> balls) {
  Eigen::Vector3d low = balls.front().centre_m;
  Eigen::Vector3d high = low;
  for (const Ball& ball : balls) {
    low = low.cwiseMin(ball.centre_m);
    high = high.cwiseMax(ball.centre_m);
  }
  return {low, high};
}

// A ball that holds `balls` (not empty): about the middle of their centres' bounding box.
Ball bounding_ball(std::span<const Ball> balls) {
  const auto [low, high] = centres_box(balls);
  Ball bound{(low + high) / 2.0, 0.0};
  for (const Ball& ball : balls) {
    bound.radius_m =
        std::max(bound.radius_m, (ball.centre_m - bound.centre_m).norm() + ball.radius_m);
  }
  return bound;
}

// Balls per tail bound: a bound per few neighbouring balls stays tight along a long arm, and is
// still several times cheaper to place than its balls.
constexpr std::size_t kBallsPerTailBound = 8;

// Bounds of groups of up to kBallsPerTailBound neighbouring balls: the balls ordered along the
// longest side of their centres' bounding box, cut into groups in that order.
std::vector<Ball> group_bounds(std::vector<Ball> balls) {
  if (balls.empty()) return {};
  const auto [low, high] = centres_box(balls);
  Eigen::Index longest = 0;
  (high - low).maxCoeff(&longest);
  std::stable_sort(balls.begin(), balls.end(), [longest](const Ball& a, const Ball& b) {
    return a.centre_m(longest) < b.centre_m(longest);
  });
  std::vector<Ball> bounds;
  for (std::size_t first = 0; first < balls.size(); first += kBallsPerTailBound) {
    const std::size_t count = std::min(kBallsPerTailBound, balls.size() - first);
    bounds.push_back(bounding_ball(std::span<const Ball>(balls).subspan(first, count)));
  }
  return bounds;
}

// Added to every tail bound, so that rounding in placing it never leaves a ball's edge outside.
constexpr double kBoundMargin_m = 1e-6;

}  // namespace

struct CellEnvelope::CellFrames {
  std::vector<double> q;
  std::vector<Eigen::Isometry3d> poses;  // of the links, base frame
  JointAxis axes[kMaxJoints];
};

CellEnvelope::CellEnvelope(const RobotModel& robot, RobotBalls balls, const CspaceGrid& grid,
                           double padding_m, const std::vector<std::size_t>& part_starts,
                           std::size_t max_head_prefixes)
    : robot_(robot), robot_balls_(std::move(balls)), grid_(grid), padding_m_(padding_m) {
  if (grid.joint_count() != robot.dof()) {
    throw std::invalid_argument("the C-space grid has " + std::to_string(grid.joint_count()) +
                                " joints, the robot '" + robot.name + "' " +
                                std::to_string(robot.dof()));
  }
  if (robot_balls_.links.size() != robot.dof()) {
    throw std::invalid_argument("the ball cover has " + std::to_string(robot_balls_.links.size()) +
                                " links, the robot " + std::to_string(robot.dof()));
  }
  if (!std::isfinite(padding_m) || padding_m < 0.0) {
    throw std::invalid_argument("padding must be finite and >= 0 m, got " +
                                std::to_string(padding_m));
  }
  for (const std::size_t start : part_starts) {
    if (start >= body_count()) {
      throw std::invalid_argument("a robot part begins at body " + std::to_string(start) +
                                  ", the robot has " + std::to_string(body_count()) + " bodies");
    }
  }
  make_tail_tables(max_head_prefixes, part_starts);
}

std::size_t CellEnvelope::prefix_count(std::size_t body) const {
  std::size_t count = 1;
  for (std::uint32_t joint = 0; joint < body; ++joint) count *= grid_.cells_along(joint);
  return count;
}

std::size_t CellEnvelope::prefix_of(const GridCoords& coords, std::size_t body) const {
  std::size_t prefix = 0;
  for (std::uint32_t joint = static_cast<std::uint32_t>(body); joint-- > 0;) {
    prefix = prefix * grid_.cells_along(joint) + coords.along[joint];
  }
  return prefix;
}

void CellEnvelope::make_tail_tables(std::size_t max_head_prefixes,
                                    const std::vector<std::size_t>& part_starts) {
  tail_body_ = 1;  // the base has no joint before it: always the head
  while (tail_body_ < body_count() && prefix_count(tail_body_) <= max_head_prefixes) ++tail_body_;
  if (tail_body_ == body_count()) return;
  segment_starts_ = {tail_body_};
  for (const std::size_t start : part_starts) {
    if (start > segment_starts_.back()) segment_starts_.push_back(start);
  }
  const std::size_t first_link = tail_body_ - 1;
  std::size_t suffixes = 1;
  for (std::size_t joint = first_link + 1; joint < grid_.joint_count(); ++joint) {
    suffixes *= grid_.cells_along(static_cast<std::uint32_t>(joint));
  }
  std::size_t balls_per_suffix = 0;
  for (std::size_t link = first_link; link < robot_balls_.links.size(); ++link) {
    balls_per_suffix += robot_balls_.links[link].size();
  }
  if (suffixes * balls_per_suffix > kMaxTailBalls) return;
  tail_tables_.assign(segment_starts_.size(), std::vector<std::vector<Ball>>(suffixes));
  std::vector<Ball> swept;
  for (std::size_t suffix = 0; suffix < suffixes; ++suffix) {
    GridCoords coords;  // the head's joints at their first cell: they do not enter
    std::size_t rest = suffix;
    for (std::size_t joint = first_link + 1; joint < grid_.joint_count(); ++joint) {
      const std::uint32_t cells = grid_.cells_along(static_cast<std::uint32_t>(joint));
      coords.along[joint] = static_cast<std::uint32_t>(rest % cells);
      rest /= cells;
    }
    const CellFrames& frames = frames_of(coords);
    const Eigen::Isometry3d to_link = frames.poses[first_link].inverse();
    for (std::size_t segment = 0; segment < segment_starts_.size(); ++segment) {
      const std::size_t end =
          segment + 1 < segment_starts_.size() ? segment_starts_[segment + 1] : body_count();
      swept.clear();
      append_link_balls(frames, segment_starts_[segment], end, first_link, swept);
      for (Ball& ball : swept) ball.centre_m = to_link * ball.centre_m;
      tail_tables_[segment][suffix] = without_covered_balls(swept);
    }
  }
  tail_bounds_.assign(segment_starts_.size(), std::vector<std::vector<Ball>>(suffixes));
  for (std::size_t segment = 0; segment < segment_starts_.size(); ++segment) {
    for (std::size_t suffix = 0; suffix < suffixes; ++suffix) {
      tail_bounds_[segment][suffix] = group_bounds(tail_tables_[segment][suffix]);
    }
  }
}

bool CellEnvelope::tail_bounds(const GridCoords& coords, std::vector<Ball>& bounds) const {
  bounds.clear();
  if (tail_bounds_.empty()) return false;
  const CellFrames& frames = frames_of(coords);
  const std::size_t first_link = tail_body_ - 1;
  // Up to 120 degrees (chord at most the radius), sweep() keeps every centre where it is, and a
  // ball within R of the bound's centre (R: the bound's radius before the sweeps) has its
  // distance from an axis within R of the centre's.
  for (std::size_t k = 0; k < first_link; ++k) {
    if (!frames.axes[k].prismatic && !(frames.axes[k].chord_per_radius <= 1.0)) return false;
  }
  const std::size_t suffix = suffix_of(coords);
  for (const auto& segment : tail_bounds_) {
    for (const Ball& local : segment[suffix]) {
      Ball bound{transform_point(frames.poses[first_link], local.centre_m),
                 local.radius_m + kBoundMargin_m};
      for (std::size_t k = first_link; k-- > 0;) {
        const JointAxis& axis = frames.axes[k];
        if (axis.prismatic) {
          bound.radius_m += axis.half_width;
          continue;
        }
        const double from_axis = (bound.centre_m - foot_on_axis(axis, bound.centre_m)).norm();
        bound.radius_m += axis.chord_per_radius * (from_axis + local.radius_m);
      }
      bounds.push_back(bound);
    }
  }
  return true;
}

void CellEnvelope::first_joint_motions(std::vector<Eigen::Isometry3d>& motions) const {
  motions.clear();
  const CellFrames& first = frames_of(GridCoords{});
  const JointAxis axis = first.axes[0];
  const double first_centre = first.q[0];
  GridCoords coords;
  for (std::uint32_t cell = 0; cell < grid_.cells_along(0); ++cell) {
    coords.along[0] = cell;
    // From the cell's own centre: the last cell ends exactly on the limit (cspace_grid.hpp).
    const double offset = grid_.cell_centre(coords).value().rad[0] - first_centre;
    if (axis.prismatic) {
      motions.emplace_back(Eigen::Translation3d(offset * axis.direction));
    } else {
      motions.emplace_back(Eigen::Translation3d(axis.point) *
                           Eigen::AngleAxisd(offset, axis.direction) *
                           Eigen::Translation3d(-axis.point));
    }
  }
}

std::size_t CellEnvelope::segment_starting_at(std::size_t body) const {
  const auto found = std::find(segment_starts_.begin(), segment_starts_.end(), body);
  return static_cast<std::size_t>(found - segment_starts_.begin());
}

std::size_t CellEnvelope::suffix_of(const GridCoords& coords) const {
  std::size_t suffix = 0;
  for (std::size_t joint = grid_.joint_count(); joint-- > tail_body_;) {
    suffix = suffix * grid_.cells_along(static_cast<std::uint32_t>(joint)) + coords.along[joint];
  }
  return suffix;
}

std::size_t CellEnvelope::tail_table_balls() const {
  std::size_t count = 0;
  for (const auto& segment : tail_tables_) {
    for (const auto& table : segment) count += table.size();
  }
  return count;
}

void CellEnvelope::append_body_balls(std::size_t body, std::size_t prefix,
                                     std::vector<Ball>& balls) const {
  GridCoords coords;
  for (std::uint32_t joint = 0; joint < body; ++joint) {
    coords.along[joint] = static_cast<std::uint32_t>(prefix % grid_.cells_along(joint));
    prefix /= grid_.cells_along(joint);
  }
  append_link_balls(frames_of(coords), body, body + 1, 0, balls);
}

void CellEnvelope::balls_of_bodies(const GridCoords& coords, std::size_t first_body,
                                   std::size_t end_body, std::vector<Ball>& balls) const {
  balls.clear();
  end_body = std::min(end_body, body_count());
  if (first_body >= end_body) return;
  const CellFrames& frames = frames_of(coords);
  const std::size_t tail_first = std::max(first_body, tail_body_);
  const std::size_t first_segment = segment_starting_at(tail_first);
  const std::size_t end_segment =
      end_body == body_count() ? segment_starts_.size() : segment_starting_at(end_body);
  // Tables only for whole segments: the range must begin and end at their bounds.
  const bool from_tables = !tail_tables_.empty() && tail_first < end_body &&
                           first_segment < end_segment &&
                           (end_body == body_count() || end_segment < segment_starts_.size());
  append_link_balls(frames, first_body, from_tables ? tail_first : end_body, 0, balls);
  if (!from_tables) return;
  const std::size_t first_link = tail_body_ - 1;
  const Eigen::Isometry3d& pose = frames.poses[first_link];
  const std::size_t suffix = suffix_of(coords);
  for (std::size_t segment = first_segment; segment < end_segment; ++segment) {
    for (const Ball& local : tail_tables_[segment][suffix]) {
      Ball ball{transform_point(pose, local.centre_m), local.radius_m};
      for (std::size_t k = first_link; k-- > 0;) sweep(frames.axes[k], ball);
      balls.push_back(ball);
    }
  }
}

const CellEnvelope::CellFrames& CellEnvelope::frames_of(const GridCoords& coords) const {
  const auto centre = grid_.cell_centre(coords);
  if (!centre.ok()) throw std::out_of_range("cell coordinates outside the C-space grid");
  // Scratch per thread, so that fusion's cycle allocates nothing after its first.
  thread_local CellFrames frames;
  const std::size_t joints = grid_.joint_count();
  frames.q.assign(centre.value().rad, centre.value().rad + joints);
  link_poses(robot_, frames.q, frames.poses);
  for (std::size_t k = 0; k < joints; ++k) {
    const double half_width = grid_.cell_width_rad(static_cast<std::uint32_t>(k)) / 2.0;
    frames.axes[k] =
        JointAxis{frames.poses[k].translation(), frames.poses[k].linear() * robot_.joints[k].axis,
                  robot_.joints[k].type == JointType::kPrismatic, half_width,
                  2.0 * std::sin(std::min(half_width, std::numbers::pi) / 2.0)};
  }
  return frames;
}

void CellEnvelope::append_link_balls(const CellFrames& frames, std::size_t first_body,
                                     std::size_t end_body, std::size_t lowest_joint,
                                     std::vector<Ball>& balls) const {
  if (first_body == 0 && end_body > 0) {
    for (const auto& ball : robot_balls_.base) {
      balls.push_back(Ball{ball.centre_m, ball.radius_m + padding_m_});
    }
  }
  for (std::size_t link = std::max<std::size_t>(first_body, 1) - 1; link + 1 < end_body; ++link) {
    for (const auto& local : robot_balls_.links[link]) {
      Ball ball{transform_point(frames.poses[link], local.centre_m), local.radius_m + padding_m_};
      for (std::size_t k = link + 1; k-- > lowest_joint;) sweep(frames.axes[k], ball);
      balls.push_back(ball);
    }
  }
}

}  // namespace safecell
