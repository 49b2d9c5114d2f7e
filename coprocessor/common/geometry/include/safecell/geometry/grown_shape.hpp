#pragma once
// A shape grown all round by a margin: what a part a few millimetres larger than its model looks
// like (cables, tolerances). Primitives grow exactly (every surface point moves out by the
// margin); a mesh's vertices move out from its vertex centroid by the margin, which holds a
// convex mesh and approximates others.

#include "safecell/geometry/shape.hpp"

namespace safecell {

// Throws std::invalid_argument for a margin that is negative or not finite.
[[nodiscard]] PlacedShape grown_by(const PlacedShape& shape, double margin_m);

}  // namespace safecell
