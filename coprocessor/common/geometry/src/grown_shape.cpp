#include "safecell/geometry/grown_shape.hpp"

#include <cmath>
#include <stdexcept>
#include <string>
#include <type_traits>

namespace safecell {
namespace {

std::shared_ptr<const TriangleMesh> grown_mesh(const TriangleMesh& mesh, double margin_m) {
  Eigen::Vector3d centroid = Eigen::Vector3d::Zero();
  for (const auto& vertex : mesh.vertices) centroid += vertex;
  if (!mesh.vertices.empty()) centroid /= static_cast<double>(mesh.vertices.size());
  auto grown = std::make_shared<TriangleMesh>(mesh);
  for (auto& vertex : grown->vertices) {
    const Eigen::Vector3d out = vertex - centroid;
    const double length = out.norm();
    if (length > 0.0) vertex += out * (margin_m / length);
  }
  return grown;
}

}  // namespace

PlacedShape grown_by(const PlacedShape& shape, double margin_m) {
  if (!(margin_m >= 0.0 && std::isfinite(margin_m))) {
    throw std::invalid_argument("grow margin must be finite and >= 0 m, got " +
                                std::to_string(margin_m));
  }
  PlacedShape grown = shape;
  std::visit(
      [&](auto& s) {
        using T = std::decay_t<decltype(s)>;
        if constexpr (std::is_same_v<T, Box>) {
          s.size_m.array() += 2.0 * margin_m;
        } else if constexpr (std::is_same_v<T, Sphere> || std::is_same_v<T, Capsule>) {
          s.radius_m += margin_m;  // a capsule's caps grow with its radius
        } else if constexpr (std::is_same_v<T, Cylinder>) {
          s.radius_m += margin_m;
          s.length_m += 2.0 * margin_m;
        } else {
          if (s) s = grown_mesh(*s, margin_m);
        }
      },
      grown.shape);
  return grown;
}

}  // namespace safecell
