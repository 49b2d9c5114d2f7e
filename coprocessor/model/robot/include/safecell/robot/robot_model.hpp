#pragma once
// A serial robot arm from base to tool: its movable joints, the links they move with their
// collision geometry, and the named frames (fixed links such as "flange") folded into them.

#include <Eigen/Geometry>
#include <optional>
#include <string>
#include <vector>

#include "safecell/geometry/shape.hpp"

namespace safecell {

enum class JointType { kRevolute, kContinuous, kPrismatic };

struct RobotJoint {
  std::string name;
  JointType type = JointType::kRevolute;
  // The joint frame at q = 0 in the frame of the link before it (fixed joints folded in).
  Eigen::Isometry3d origin = Eigen::Isometry3d::Identity();
  Eigen::Vector3d axis = Eigen::Vector3d::UnitZ();  // unit, in the joint frame
  double lower = 0.0;                               // rad (m for prismatic)
  double upper = 0.0;
  double max_speed = 0.0;  // rad/s (m/s); 0 when the URDF gives none
};

struct RobotLink {
  std::string name;
  std::vector<PlacedShape> collision;  // in this link's frame
  std::vector<PlacedShape> visual;     // what the link looks like; may be empty
};

// A link of the URDF that was folded into a movable link (or the base) by fixed joints.
struct NamedFrame {
  std::string name;
  int link = -1;  // -1: the base; otherwise the index of the movable link (= its joint)
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();  // in that link's frame
};

struct RobotModel {
  std::string name;
  std::string source;  // file path or "built-in ..."
  RobotLink base;
  std::vector<RobotJoint> joints;  // from base to tool
  std::vector<RobotLink> links;    // links[j] is moved by joints[j]
  std::vector<NamedFrame> frames;  // every URDF link, movable ones included

  std::size_t dof() const { return joints.size(); }
  std::optional<NamedFrame> frame(const std::string& link_name) const;
};

}  // namespace safecell
