#include "safecell/silhouettes/configuration_silhouettes.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "safecell/robot/kinematics.hpp"

namespace safecell {

std::optional<double> removal_widening_m(const RobotModel& robot, const CspaceGrid& grid,
                                         double padding_m, double sync_error_s) {
  if (grid.joint_count() != robot.dof()) {
    throw std::invalid_argument("a grid of " + std::to_string(grid.joint_count()) +
                                " joints for a robot of " + std::to_string(robot.dof()));
  }
  double motion_m = 0.0;
  for (std::uint32_t j = 0; j < grid.joint_count(); ++j) {
    const double speed = robot.joints[j].max_speed;
    if (sync_error_s > 0.0 && !(speed > 0.0)) return std::nullopt;
    motion_m += grid.joint(j).l_m * speed * sync_error_s;
  }
  return padding_m + motion_m;
}

ConfigurationSilhouettes::ConfigurationSilhouettes(const CellModel& cell, double ball_radius_m,
                                                   double widening_m)
    : widening_m_(widening_m) {
  if (!cell.robot) {
    throw std::invalid_argument("cell '" + cell.config.name +
                                "' names no robot model; robot removal at the configuration "
                                "needs one");
  }
  if (cell.cameras.empty())
    throw std::invalid_argument("cell '" + cell.config.name + "' has no camera");
  if (!is_ball_radius(ball_radius_m)) {
    throw std::invalid_argument("ball radius must be " + ball_radius_range() + ", got " +
                                std::to_string(ball_radius_m));
  }
  if (!(widening_m >= 0.0 && widening_m <= 1.0)) {
    throw std::invalid_argument("robot removal widening must be 0..1 m, got " +
                                std::to_string(widening_m));
  }
  robot_ = *cell.robot;
  balls_ = cover_with_balls(robot_, ball_radius_m);
  for (auto& ball : balls_.base) ball.radius_m += widening_m;
  for (auto& link : balls_.links) {
    for (auto& ball : link) ball.radius_m += widening_m;
  }
  for (const auto& camera : cell.cameras) projections_.emplace_back(camera, cell.feature_grid);
}

void ConfigurationSilhouettes::add_silhouettes(std::span<const double> q,
                                               std::vector<FeatureMask>& masks) const {
  add_silhouettes(q, masks, 0, 1 + balls_.links.size());
}

void ConfigurationSilhouettes::add_silhouettes(std::span<const double> q,
                                               std::vector<FeatureMask>& masks,
                                               std::size_t first_body, std::size_t end_body) const {
  if (masks.size() != projections_.size() || q.size() != robot_.dof()) {
    throw std::invalid_argument(std::to_string(masks.size()) + " masks and " +
                                std::to_string(q.size()) + " joint values for " +
                                std::to_string(projections_.size()) + " cameras and " +
                                std::to_string(robot_.dof()) + " joints");
  }
  thread_local std::vector<Ball> placed;
  place_balls(q, first_body, end_body, placed);
  for (std::size_t camera = 0; camera < projections_.size(); ++camera) {
    add_ball_rects(projections_[camera], placed, masks[camera]);
  }
}

void ConfigurationSilhouettes::place_balls(std::span<const double> q, std::size_t first_body,
                                           std::size_t end_body, std::vector<Ball>& balls) const {
  if (q.size() != robot_.dof()) {
    throw std::invalid_argument(std::to_string(q.size()) + " joint values for " +
                                std::to_string(robot_.dof()) + " joints");
  }
  thread_local std::vector<Eigen::Isometry3d> poses;
  thread_local std::vector<double> joints;
  joints.assign(q.begin(), q.end());
  link_poses(robot_, joints, poses);
  balls.clear();
  if (first_body == 0 && end_body > 0) balls.assign(balls_.base.begin(), balls_.base.end());
  // Body 1 + link is link `link`.
  const std::size_t links_end = std::min(end_body, 1 + balls_.links.size());
  for (std::size_t body = std::max<std::size_t>(first_body, 1); body < links_end; ++body) {
    const std::size_t link = body - 1;
    for (const Ball& ball : balls_.links[link]) {
      balls.push_back(Ball{poses[link] * ball.centre_m, ball.radius_m});
    }
  }
}

}  // namespace safecell
