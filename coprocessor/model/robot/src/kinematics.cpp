#include "safecell/robot/kinematics.hpp"

#include <algorithm>
#include <stdexcept>

namespace safecell {
namespace {

Eigen::Isometry3d joint_motion(const RobotJoint& joint, double q) {
  Eigen::Isometry3d motion = Eigen::Isometry3d::Identity();
  if (joint.type == JointType::kPrismatic) {
    motion.translation() = q * joint.axis;
  } else {
    motion.linear() = Eigen::AngleAxisd(q, joint.axis).toRotationMatrix();
  }
  return motion;
}

}  // namespace

void link_poses(const RobotModel& model, const std::vector<double>& q,
                std::vector<Eigen::Isometry3d>& poses) {
  if (q.size() != model.dof()) {
    throw std::invalid_argument("robot '" + model.name + "' has " + std::to_string(model.dof()) +
                                " joints, got " + std::to_string(q.size()) + " joint values");
  }
  poses.clear();
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  for (std::size_t j = 0; j < model.dof(); ++j) {
    pose = pose * model.joints[j].origin * joint_motion(model.joints[j], q[j]);
    poses.push_back(pose);
  }
}

std::vector<Eigen::Isometry3d> link_poses(const RobotModel& model, const std::vector<double>& q) {
  std::vector<Eigen::Isometry3d> poses;
  poses.reserve(model.dof());
  link_poses(model, q, poses);
  return poses;
}

Eigen::Isometry3d frame_pose(const RobotModel& model, const std::vector<double>& q,
                             const std::string& frame_name) {
  const auto frame = model.frame(frame_name);
  if (!frame)
    throw std::invalid_argument("robot '" + model.name + "' has no frame '" + frame_name + "'");
  if (frame->link < 0) return frame->pose;
  return link_poses(model, q)[static_cast<std::size_t>(frame->link)] * frame->pose;
}

namespace {

// The shapes `pick` chooses from the bodies in `bodies`, placed by the link poses.
template <typename Pick>
std::vector<PlacedShape> placed_shapes(const RobotModel& model, const std::vector<double>& q,
                                       const Eigen::Isometry3d& base_pose, BodyRange bodies,
                                       Pick pick) {
  const auto poses = link_poses(model, q);
  std::vector<PlacedShape> shapes;
  if (bodies.first == 0 && bodies.end > 0) {
    for (const auto& shape : pick(model.base)) {
      shapes.push_back(PlacedShape{shape.shape, base_pose * shape.pose});
    }
  }
  const std::size_t end_link = std::min(model.dof(), std::max<std::size_t>(bodies.end, 1) - 1);
  for (std::size_t j = std::max<std::size_t>(bodies.first, 1) - 1; j < end_link; ++j) {
    for (const auto& shape : pick(model.links[j])) {
      shapes.push_back(PlacedShape{shape.shape, base_pose * poses[j] * shape.pose});
    }
  }
  return shapes;
}

}  // namespace

std::vector<PlacedShape> collision_shapes_at(const RobotModel& model, const std::vector<double>& q,
                                             const Eigen::Isometry3d& base_pose, BodyRange bodies) {
  return placed_shapes(
      model, q, base_pose, bodies,
      [](const RobotLink& link) -> const std::vector<PlacedShape>& { return link.collision; });
}

std::vector<PlacedShape> visual_shapes_at(const RobotModel& model, const std::vector<double>& q,
                                          const Eigen::Isometry3d& base_pose, BodyRange bodies) {
  return placed_shapes(model, q, base_pose, bodies,
                       [](const RobotLink& link) -> const std::vector<PlacedShape>& {
                         return link.visual.empty() ? link.collision : link.visual;
                       });
}

}  // namespace safecell
