#include "mesh_containment.hpp"

#include <cmath>
#include <limits>

namespace safecell {
namespace {

// Moeller-Trumbore: does the ray origin + t direction, t > 0, cross the triangle abc?
bool ray_crosses(const Eigen::Vector3d& origin, const Eigen::Vector3d& direction,
                 const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c) {
  const Eigen::Vector3d edge_ab = b - a;
  const Eigen::Vector3d edge_ac = c - a;
  const Eigen::Vector3d normal_to_ac = direction.cross(edge_ac);
  const double determinant = edge_ab.dot(normal_to_ac);
  if (std::abs(determinant) < std::numeric_limits<double>::min()) return false;  // parallel
  const Eigen::Vector3d from_a = origin - a;
  const double u = from_a.dot(normal_to_ac) / determinant;
  if (u < 0.0 || u > 1.0) return false;
  const Eigen::Vector3d normal_to_ab = from_a.cross(edge_ab);
  const double v = direction.dot(normal_to_ab) / determinant;
  if (v < 0.0 || u + v > 1.0) return false;
  return edge_ac.dot(normal_to_ab) / determinant > 0.0;
}

}  // namespace

bool mesh_contains_point(const TriangleMesh& mesh, const Eigen::Vector3d& point) {
  const Eigen::Vector3d direction = Eigen::Vector3d(0.5377, 0.3218, 0.7795).normalized();
  bool inside = false;
  for (const auto& triangle : mesh.triangles) {
    if (ray_crosses(point, direction, mesh.vertices[triangle[0]], mesh.vertices[triangle[1]],
                    mesh.vertices[triangle[2]])) {
      inside = !inside;
    }
  }
  return inside;
}

}  // namespace safecell
