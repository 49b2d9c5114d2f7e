#pragma once
// Whether a point lies inside a closed triangle mesh (internal to the sim module).

#include <Eigen/Core>

#include "safecell/geometry/shape.hpp"

namespace safecell {

// Ray parity: a point is inside when a ray from it crosses the surface an odd number of times.
// Needs a closed mesh; the winding of the triangles does not matter. The ray runs in a fixed
// oblique direction, so a point on a hand-built box mesh's diagonal or edge planes does not send
// it through an edge; a ray that grazes an edge of a general mesh may miscount.
bool mesh_contains_point(const TriangleMesh& mesh, const Eigen::Vector3d& point);

}  // namespace safecell
