#include "safecell/geometry/shape_bounds.hpp"

#include <algorithm>
#include <cmath>

#include "safecell/geometry/tessellate.hpp"

namespace safecell {

std::vector<Eigen::Vector3d> extreme_points(const PlacedShape& placed, int segments) {
  return tessellate(placed, segments).vertices;
}

double bounding_radius_m(const Shape& shape) {
  return std::visit(
      [](const auto& s) -> double {
        using T = std::decay_t<decltype(s)>;
        if constexpr (std::is_same_v<T, Box>) {
          return s.size_m.norm() / 2.0;
        } else if constexpr (std::is_same_v<T, Sphere>) {
          return s.radius_m;
        } else if constexpr (std::is_same_v<T, Cylinder>) {
          return std::hypot(s.radius_m, s.length_m / 2.0);
        } else if constexpr (std::is_same_v<T, Capsule>) {
          return s.length_m / 2.0 + s.radius_m;
        } else {
          double radius = 0.0;
          for (const auto& vertex : s->vertices) radius = std::max(radius, vertex.norm());
          return radius;
        }
      },
      shape);
}

}  // namespace safecell
