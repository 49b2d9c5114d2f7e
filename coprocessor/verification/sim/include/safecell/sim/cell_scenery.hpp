#pragma once
// The still parts of the simulated cell: a tiled floor, tiled walls and a ceiling (the tiles'
// different brightness gives the feature images texture to work with), and the static boxes.

#include <Eigen/Core>
#include <vector>

#include "safecell/geometry/shape.hpp"
#include "safecell/sim/surface_mesh.hpp"

namespace safecell {

// size_m: the inside of the cell, floor centre at the origin, z up. Boxes are rendered as given,
// box b as static obstacle b in the object-id image; the rest is background.
std::vector<SurfaceMesh> cell_scenery(const Eigen::Vector3d& size_m,
                                      const std::vector<PlacedShape>& boxes);

}  // namespace safecell
