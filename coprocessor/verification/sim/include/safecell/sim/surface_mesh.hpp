#pragma once
// A triangle mesh in the cell frame with the brightness of its surface, ready to render.

#include <cstdint>
#include <vector>

#include "safecell/geometry/shape.hpp"
#include "safecell/sim/body_id.hpp"

namespace safecell {

struct SurfaceMesh {
  TriangleMesh mesh;
  std::uint8_t albedo = 128;  // brightness when lit head-on, 0..255
  BodyCode body = 0;          // what the object-id image shows where it is front-most
};

// Tessellates placed shapes (circumscribed, as everywhere) into one mesh of the given albedo.
SurfaceMesh surface_of(const std::vector<PlacedShape>& shapes, std::uint8_t albedo,
                       BodyCode body = 0, int segments = 16);

}  // namespace safecell
