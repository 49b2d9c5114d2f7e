#include "safecell/lut/cell_envelope.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

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

// Grows `ball` (base frame) so that it holds the ball turned or shifted by the joint.
void sweep(const JointAxis& axis, Ball& ball) {
  if (axis.prismatic) {
    ball.radius_m += axis.half_width;
    return;
  }
  const Eigen::Vector3d offset = ball.centre_m - axis.point;
  const Eigen::Vector3d foot = axis.point + offset.dot(axis.direction) * axis.direction;
  const double r = (ball.centre_m - foot).norm();
  const double chord = axis.chord_per_radius * r;
  if (r < chord) {
    ball.centre_m = foot;
    ball.radius_m += r;
  } else {
    ball.radius_m += chord;
  }
}

}  // namespace

CellEnvelope::CellEnvelope(const RobotModel& robot, RobotBalls balls, const CspaceGrid& grid,
                           double padding_m)
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
}

std::size_t CellEnvelope::prefix_count(std::size_t body) const {
  std::size_t count = 1;
  for (std::uint32_t joint = 0; joint < body; ++joint) count *= grid_.cells_along(joint);
  return count;
}

std::size_t CellEnvelope::first_uncached_body(std::size_t max_prefixes) const {
  std::size_t body = 0;
  while (body < body_count() && prefix_count(body) <= max_prefixes) ++body;
  return body;
}

std::size_t CellEnvelope::prefix_of(const GridCoords& coords, std::size_t body) const {
  std::size_t prefix = 0;
  for (std::uint32_t joint = static_cast<std::uint32_t>(body); joint-- > 0;) {
    prefix = prefix * grid_.cells_along(joint) + coords.along[joint];
  }
  return prefix;
}

void CellEnvelope::append_body_balls(std::size_t body, std::size_t prefix,
                                     std::vector<Ball>& balls) const {
  GridCoords coords;
  for (std::uint32_t joint = 0; joint < body; ++joint) {
    coords.along[joint] = static_cast<std::uint32_t>(prefix % grid_.cells_along(joint));
    prefix /= grid_.cells_along(joint);
  }
  append_balls(coords, body, body + 1, balls);
}

void CellEnvelope::balls_of_bodies(const GridCoords& coords, std::size_t first_body,
                                   std::vector<Ball>& balls) const {
  balls.clear();
  append_balls(coords, first_body, body_count(), balls);
}

void CellEnvelope::append_balls(const GridCoords& coords, std::size_t first_body,
                                std::size_t end_body, std::vector<Ball>& balls) const {
  const auto centre = grid_.cell_centre(coords);
  if (!centre.ok()) throw std::out_of_range("cell coordinates outside the C-space grid");
  const std::size_t joints = grid_.joint_count();
  // Scratch per thread, so that fusion's cycle allocates nothing after its first.
  thread_local std::vector<double> q;
  thread_local std::vector<Eigen::Isometry3d> poses;
  q.assign(centre.value().rad, centre.value().rad + joints);
  link_poses(robot_, q, poses);
  if (first_body == 0 && end_body > 0) {
    for (const auto& ball : robot_balls_.base) {
      balls.push_back(Ball{ball.centre_m, ball.radius_m + padding_m_});
    }
  }
  JointAxis axes[kMaxJoints];
  for (std::size_t k = 0; k < joints; ++k) {
    const double half_width = grid_.cell_width_rad(static_cast<std::uint32_t>(k)) / 2.0;
    axes[k] = JointAxis{poses[k].translation(), poses[k].linear() * robot_.joints[k].axis,
                        robot_.joints[k].type == JointType::kPrismatic, half_width,
                        2.0 * std::sin(std::min(half_width, std::numbers::pi) / 2.0)};
  }
  for (std::size_t link = std::max<std::size_t>(first_body, 1) - 1; link + 1 < end_body; ++link) {
    for (const auto& local : robot_balls_.links[link]) {
      Ball ball{poses[link] * local.centre_m, local.radius_m + padding_m_};
      for (std::size_t k = link + 1; k-- > 0;) sweep(axes[k], ball);
      balls.push_back(ball);
    }
  }
}

}  // namespace safecell
