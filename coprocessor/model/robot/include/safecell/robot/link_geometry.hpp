#pragma once
// What geometry each link of a robot model holds, for a user to check against the robot: the
// shapes by kind, the triangles of its meshes and the box that bounds them in the link's frame.

#include <Eigen/Geometry>
#include <cstddef>
#include <string>
#include <vector>

#include "safecell/robot/robot_model.hpp"

namespace safecell {

struct LinkGeometry {
  std::string link;
  std::size_t boxes = 0;
  std::size_t spheres = 0;
  std::size_t cylinders = 0;
  std::size_t capsules = 0;
  std::size_t meshes = 0;
  std::size_t triangles = 0;     // of the meshes
  Eigen::AlignedBox3d bounds_m;  // in the link's frame; empty when the link has no shape

  std::size_t shapes() const { return boxes + spheres + cylinders + capsules + meshes; }
};

// The collision geometry of the base, then of each moving link in chain order.
std::vector<LinkGeometry> collision_geometry_of(const RobotModel& robot);

// "2 meshes, 1 box" or "none".
std::string shape_list(const LinkGeometry& geometry);

}  // namespace safecell
