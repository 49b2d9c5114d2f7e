#pragma once
// A triangle mesh in the cell frame with the brightness of its surface, ready to render.

#include <cstdint>
#include <vector>

#include "safecell/geometry/shape.hpp"

namespace safecell {

struct SurfaceMesh {
  TriangleMesh mesh;
  std::uint8_t albedo = 128;  // brightness when lit head-on, 0..255
};

// Tessellates placed shapes (circumscribed, as everywhere) into one mesh of the given albedo.
SurfaceMesh surface_of(const std::vector<PlacedShape>& shapes, std::uint8_t albedo,
                       int segments = 16);

}  // namespace safecell
