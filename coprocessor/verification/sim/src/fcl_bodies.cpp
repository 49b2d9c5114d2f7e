#include "fcl_bodies.hpp"

#include <fcl/geometry/shape/box.h>
#include <fcl/geometry/shape/capsule.h>
#include <fcl/geometry/shape/cylinder.h>
#include <fcl/geometry/shape/sphere.h>

#include <cmath>
#include <cstdint>
#include <initializer_list>
#include <stdexcept>
#include <type_traits>
#include <variant>

#include "number_text.hpp"

namespace safecell {
namespace {

// Throws unless every size is finite and above 0 (or 0 itself, when `zero_allowed`); the message
// names field.member.
void check_sizes(const std::string& field, const char* member, std::initializer_list<double> sizes,
                 bool zero_allowed = false) {
  for (const double size : sizes) {
    if (std::isfinite(size) && (size > 0.0 || (zero_allowed && size == 0.0))) continue;
    throw std::invalid_argument(field + "." + member + ": value " + number_text(size) +
                                ", expected a finite size " +
                                (zero_allowed ? "of at least 0 m" : "above 0 m"));
  }
}

void check_mesh(const std::string& field, const TriangleMesh& mesh) {
  if (mesh.triangles.empty()) throw std::invalid_argument(field + ": mesh without triangles");
  for (const auto& vertex : mesh.vertices) {
    if (!vertex.allFinite()) throw std::invalid_argument(field + ": non-finite mesh vertex");
  }
  for (const auto& triangle : mesh.triangles) {
    for (const std::uint32_t index : triangle) {
      if (index >= mesh.vertices.size()) {
        throw std::invalid_argument(field + ": triangle index " + std::to_string(index) +
                                    " beyond the mesh's " + std::to_string(mesh.vertices.size()) +
                                    " vertices");
      }
    }
  }
}

std::shared_ptr<MeshHierarchy> build_hierarchy(const TriangleMesh& mesh) {
  std::vector<fcl::Vector3d> vertices(mesh.vertices.begin(), mesh.vertices.end());
  std::vector<fcl::Triangle> triangles;
  triangles.reserve(mesh.triangles.size());
  for (const auto& [a, b, c] : mesh.triangles) triangles.emplace_back(a, b, c);
  auto hierarchy = std::make_shared<MeshHierarchy>();
  hierarchy->beginModel(static_cast<int>(triangles.size()), static_cast<int>(vertices.size()));
  hierarchy->addSubModel(vertices, triangles);
  hierarchy->endModel();
  return hierarchy;
}

// The FCL geometry of a shape; `field` names it in error messages.
std::shared_ptr<fcl::CollisionGeometryd> geometry_of(const Shape& shape, const std::string& field,
                                                     MeshHierarchyCache& cache) {
  return std::visit(
      [&](const auto& s) -> std::shared_ptr<fcl::CollisionGeometryd> {
        using T = std::decay_t<decltype(s)>;
        if constexpr (std::is_same_v<T, Box>) {
          check_sizes(field, "size_m", {s.size_m.x(), s.size_m.y(), s.size_m.z()});
          return std::make_shared<fcl::Boxd>(s.size_m);
        } else if constexpr (std::is_same_v<T, Sphere>) {
          check_sizes(field, "radius_m", {s.radius_m});
          return std::make_shared<fcl::Sphered>(s.radius_m);
        } else if constexpr (std::is_same_v<T, Cylinder>) {
          check_sizes(field, "radius_m", {s.radius_m});
          check_sizes(field, "length_m", {s.length_m});
          return std::make_shared<fcl::Cylinderd>(s.radius_m, s.length_m);
        } else if constexpr (std::is_same_v<T, Capsule>) {
          check_sizes(field, "radius_m", {s.radius_m});
          check_sizes(field, "length_m", {s.length_m}, true);
          return std::make_shared<fcl::Capsuled>(s.radius_m, s.length_m);
        } else {
          if (!s) throw std::invalid_argument(field + ": null mesh");
          return cache.hierarchy_of(s, field);
        }
      },
      shape);
}

FclBody make_body(const PlacedShape& placed, const std::string& field, MeshHierarchyCache& cache) {
  if (!placed.pose.matrix().allFinite()) throw std::invalid_argument(field + ".pose: not finite");
  const auto* mesh = std::get_if<std::shared_ptr<const TriangleMesh>>(&placed.shape);
  FclBody body{fcl::CollisionObjectd(geometry_of(placed.shape, field, cache), placed.pose),
               mesh != nullptr ? *mesh : nullptr, placed.pose.translation()};
  // A primitive's origin is its centre, inside it; a mesh's origin need not touch it.
  if (body.mesh) body.inner_point_m = placed.pose * body.mesh->vertices.front();
  return body;
}

}  // namespace

std::shared_ptr<MeshHierarchy> MeshHierarchyCache::hierarchy_of(
    const std::shared_ptr<const TriangleMesh>& mesh, const std::string& field) {
  const auto found = entries_.find(mesh.get());
  if (found != entries_.end() && found->second.mesh.lock() == mesh) return found->second.hierarchy;
  std::erase_if(entries_, [](const auto& entry) { return entry.second.mesh.expired(); });
  check_mesh(field, *mesh);
  auto hierarchy = build_hierarchy(*mesh);
  entries_[mesh.get()] = Entry{mesh, hierarchy};
  return hierarchy;
}

std::vector<FclBody> make_fcl_bodies(const std::vector<PlacedShape>& shapes,
                                     const std::string& name, MeshHierarchyCache& cache) {
  std::vector<FclBody> bodies;
  bodies.reserve(shapes.size());
  for (std::size_t i = 0; i < shapes.size(); ++i) {
    bodies.push_back(make_body(shapes[i], name + "[" + std::to_string(i) + "]", cache));
  }
  return bodies;
}

}  // namespace safecell
