#include "safecell/sim/surface_mesh.hpp"

#include "safecell/geometry/tessellate.hpp"

namespace safecell {

SurfaceMesh surface_of(const std::vector<PlacedShape>& shapes, std::uint8_t albedo, BodyCode body,
                       int segments) {
  SurfaceMesh surface;
  surface.albedo = albedo;
  surface.body = body;
  for (const auto& shape : shapes) {
    const TriangleMesh part = tessellate(shape, segments);
    const auto offset = static_cast<std::uint32_t>(surface.mesh.vertices.size());
    surface.mesh.vertices.insert(surface.mesh.vertices.end(), part.vertices.begin(),
                                 part.vertices.end());
    for (const auto& triangle : part.triangles) {
      surface.mesh.triangles.push_back(
          {triangle[0] + offset, triangle[1] + offset, triangle[2] + offset});
    }
  }
  return surface;
}

}  // namespace safecell
