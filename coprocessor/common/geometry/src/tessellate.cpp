#include "safecell/geometry/tessellate.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace safecell {
namespace {

using Triangle = std::array<std::uint32_t, 3>;

std::uint32_t add_vertex(TriangleMesh& mesh, const Eigen::Vector3d& vertex) {
  mesh.vertices.push_back(vertex);
  return static_cast<std::uint32_t>(mesh.vertices.size() - 1);
}

TriangleMesh box_mesh(const Box& box) {
  TriangleMesh mesh;
  const Eigen::Vector3d half = box.size_m / 2.0;
  for (int corner = 0; corner < 8; ++corner) {
    add_vertex(mesh,
               {(corner & 1) != 0 ? half.x() : -half.x(), (corner & 2) != 0 ? half.y() : -half.y(),
                (corner & 4) != 0 ? half.z() : -half.z()});
  }
  // Two triangles per face, counter-clockwise seen from outside.
  mesh.triangles = {{0, 2, 1}, {1, 2, 3}, {4, 5, 6}, {5, 7, 6}, {0, 1, 4}, {1, 5, 4},
                    {2, 6, 3}, {3, 6, 7}, {0, 4, 2}, {2, 4, 6}, {1, 3, 5}, {3, 7, 5}};
  return mesh;
}

// A surface of revolution about z, given as rings (z, radius) from bottom to top; a ring of
// radius 0 is a pole. The rings' radii must already be circumscribed.
TriangleMesh revolve(const std::vector<std::pair<double, double>>& rings, int segments) {
  TriangleMesh mesh;
  std::vector<std::vector<std::uint32_t>> ring_vertices;
  for (const auto& [z, radius] : rings) {
    std::vector<std::uint32_t> ring;
    const int count = radius == 0.0 ? 1 : segments;
    for (int s = 0; s < count; ++s) {
      const double angle = 2.0 * std::numbers::pi * s / segments;
      ring.push_back(add_vertex(mesh, {radius * std::cos(angle), radius * std::sin(angle), z}));
    }
    ring_vertices.push_back(std::move(ring));
  }
  for (std::size_t r = 0; r + 1 < ring_vertices.size(); ++r) {
    const auto& lower = ring_vertices[r];
    const auto& upper = ring_vertices[r + 1];
    for (std::size_t s = 0; s < static_cast<std::size_t>(segments); ++s) {
      const std::size_t next = (s + 1) % static_cast<std::size_t>(segments);
      const auto at = [](const std::vector<std::uint32_t>& ring, std::size_t k) {
        return ring.size() == 1 ? ring[0] : ring[k];
      };
      if (lower.size() > 1) mesh.triangles.push_back({at(lower, s), at(lower, next), at(upper, s)});
      if (upper.size() > 1) {
        mesh.triangles.push_back({at(lower, next), at(upper, next), at(upper, s)});
      }
    }
  }
  return mesh;
}

// Scale that makes a polygon of `segments` sides circumscribe its circle.
double ring_scale(int segments) { return 1.0 / std::cos(std::numbers::pi / segments); }

// Rings of a sphere cap from `from` to `to` polar angle (0 = top pole), centred at height z0,
// scaled so that every facet lies outside the sphere.
void add_sphere_rings(std::vector<std::pair<double, double>>& rings, double radius, double z0,
                      double from, double to, int stacks, int segments) {
  const double stack = std::numbers::pi / (2.0 * stacks);
  const double half_diagonal = std::hypot(std::numbers::pi / segments, stack / 2.0);
  const double scaled = radius / std::cos(half_diagonal);
  const int count = static_cast<int>(std::lround(std::abs(to - from) / stack));
  for (int k = 0; k <= count; ++k) {
    const double polar = from + (to - from) * k / count;
    const double ring_radius = std::abs(std::sin(polar)) < 1e-12 ? 0.0 : scaled * std::sin(polar);
    rings.emplace_back(z0 + scaled * std::cos(polar), ring_radius);
  }
}

TriangleMesh capsule_mesh(double radius, double length, int segments) {
  const int stacks = std::max(2, segments / 4);  // per hemisphere
  std::vector<std::pair<double, double>> rings;
  add_sphere_rings(rings, radius, -length / 2.0, std::numbers::pi, std::numbers::pi / 2.0, stacks,
                   segments);
  std::vector<std::pair<double, double>> top;
  add_sphere_rings(top, radius, length / 2.0, std::numbers::pi / 2.0, 0.0, stacks, segments);
  // The equator rings of both hemispheres join with the cylinder part; skip the duplicate when
  // the capsule is a sphere.
  const std::size_t skip = length == 0.0 ? 1 : 0;
  rings.insert(rings.end(), top.begin() + static_cast<std::ptrdiff_t>(skip), top.end());
  return revolve(rings, segments);
}

TriangleMesh cylinder_mesh(const Cylinder& cylinder, int segments) {
  const double radius = cylinder.radius_m * ring_scale(segments);
  const double half = cylinder.length_m / 2.0;
  return revolve({{-half, 0.0}, {-half, radius}, {half, radius}, {half, 0.0}}, segments);
}

}  // namespace

TriangleMesh tessellate(const Shape& shape, int segments) {
  segments = std::max(segments, 8);
  return std::visit(
      [segments](const auto& s) -> TriangleMesh {
        using T = std::decay_t<decltype(s)>;
        if constexpr (std::is_same_v<T, Box>) {
          return box_mesh(s);
        } else if constexpr (std::is_same_v<T, Sphere>) {
          return capsule_mesh(s.radius_m, 0.0, segments);
        } else if constexpr (std::is_same_v<T, Cylinder>) {
          return cylinder_mesh(s, segments);
        } else if constexpr (std::is_same_v<T, Capsule>) {
          return capsule_mesh(s.radius_m, s.length_m, segments);
        } else {
          return *s;
        }
      },
      shape);
}

TriangleMesh tessellate(const PlacedShape& placed, int segments) {
  TriangleMesh mesh = tessellate(placed.shape, segments);
  for (auto& vertex : mesh.vertices) vertex = placed.pose * vertex;
  return mesh;
}

}  // namespace safecell
