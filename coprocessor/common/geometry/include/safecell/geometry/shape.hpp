#pragma once
// Solid shapes in their own frame, and shapes placed in a parent frame. Lengths in metres.
// Cylinders and capsules run along their local z axis and are centred on their origin, as in URDF.

#include <Eigen/Geometry>
#include <array>
#include <cstdint>
#include <memory>
#include <variant>
#include <vector>

namespace safecell {

struct Box {
  Eigen::Vector3d size_m = Eigen::Vector3d::Zero();  // full edge lengths along x, y, z
};

struct Sphere {
  double radius_m = 0.0;
};

struct Cylinder {
  double radius_m = 0.0;
  double length_m = 0.0;
};

// A cylinder of length_m capped by two hemispheres: total extent length_m + 2 radius_m.
struct Capsule {
  double radius_m = 0.0;
  double length_m = 0.0;
};

struct TriangleMesh {
  std::vector<Eigen::Vector3d> vertices;
  // Indices into vertices. Winding is not consistent: renderers must not cull back faces.
  std::vector<std::array<std::uint32_t, 3>> triangles;
};

using Shape = std::variant<Box, Sphere, Cylinder, Capsule, std::shared_ptr<const TriangleMesh>>;

struct PlacedShape {
  Shape shape;
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();  // shape frame -> parent frame
};

}  // namespace safecell
