#pragma once
// Points that bound a shape for convex measures: every convex function of position (a distance
// from a line, from a point, a coordinate) takes its maximum over the shape at one of them.

#include <vector>

#include "safecell/geometry/shape.hpp"

namespace safecell {

// The vertices of the circumscribed tessellation, in the parent frame of the placed shape.
std::vector<Eigen::Vector3d> extreme_points(const PlacedShape& placed, int segments = 48);

// Largest distance of any point of the shape from its own origin.
double bounding_radius_m(const Shape& shape);

}  // namespace safecell
