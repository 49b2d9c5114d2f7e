#pragma once
// Forward kinematics: where every link and every collision shape is for joint values q.

#include <Eigen/Geometry>
#include <cstddef>
#include <limits>
#include <vector>

#include "safecell/robot/robot_model.hpp"

namespace safecell {

// Poses of links[0..dof-1] in the base frame. Precondition: q.size() == model.dof() (checked,
// std::invalid_argument).
std::vector<Eigen::Isometry3d> link_poses(const RobotModel& model, const std::vector<double>& q);
// The same into `poses` (cleared first): no allocation once it has held dof() poses.
void link_poses(const RobotModel& model, const std::vector<double>& q,
                std::vector<Eigen::Isometry3d>& poses);

// Pose of a named frame (e.g. "flange") in the base frame.
Eigen::Isometry3d frame_pose(const RobotModel& model, const std::vector<double>& q,
                             const std::string& frame_name);

// Bodies first..end-1 of the robot: 0 is the base, body j + 1 is link j (robot_parts.hpp). The
// default is every body.
struct BodyRange {
  std::size_t first = 0;
  std::size_t end = std::numeric_limits<std::size_t>::max();
};

// Every collision shape of the bodies in `bodies` (default: base and links), placed in the frame
// `base_pose` maps the base into.
std::vector<PlacedShape> collision_shapes_at(
    const RobotModel& model, const std::vector<double>& q,
    const Eigen::Isometry3d& base_pose = Eigen::Isometry3d::Identity(), BodyRange bodies = {});

// What the robot looks like: each link's visual shapes, or its collision shapes where the URDF
// gives no visual ones.
std::vector<PlacedShape> visual_shapes_at(
    const RobotModel& model, const std::vector<double>& q,
    const Eigen::Isometry3d& base_pose = Eigen::Isometry3d::Identity(), BodyRange bodies = {});

}  // namespace safecell
