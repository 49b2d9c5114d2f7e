#pragma once
// Triangle meshes of shapes, for rendering and for bounds. Curved surfaces are tessellated
// *circumscribed*: every point of the true shape lies inside the mesh, so a silhouette or an
// extent taken from the mesh is never smaller than the shape's (conservative).

#include "safecell/geometry/shape.hpp"

namespace safecell {

// segments: facets around a circle (at least 8). A mesh shape is returned as it is.
TriangleMesh tessellate(const Shape& shape, int segments = 24);

// As tessellate(), with the vertices moved into the parent frame by the shape's pose.
TriangleMesh tessellate(const PlacedShape& placed, int segments = 24);

}  // namespace safecell
