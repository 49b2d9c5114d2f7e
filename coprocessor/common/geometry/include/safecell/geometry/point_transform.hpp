#pragma once
// A rigid transform applied to one point, written out.

#include <Eigen/Geometry>

namespace safecell {

// pose * point. At -O2, GCC leaves Eigen's Isometry3d * Vector3d as an out-of-line call, which
// cost more than its arithmetic in the table build's loops over every ball of every C-space cell.
[[nodiscard]] inline Eigen::Vector3d transform_point(const Eigen::Isometry3d& pose,
                                                     const Eigen::Vector3d& point) {
  return pose.linear() * point + pose.translation();
}

}  // namespace safecell
