#pragma once
// The static part of the forbidden map (paper §4): the cells in which the robot could touch a
// static obstacle (a table, a fence, a machine). Static obstacles never appear in the difference
// images, so they are computed once from their geometry: a cell is forbidden when a ball of its
// envelope (cell_envelope.hpp) reaches an obstacle. Boxes are tested exactly, other shapes by
// their bounding sphere.

#include <vector>

#include "safecell/cellsets/cell_set.hpp"
#include "safecell/compute/parallel_chunks.hpp"
#include "safecell/envelope/cell_envelope.hpp"
#include "safecell/geometry/shape.hpp"

namespace safecell {

// Whether the ball reaches the placed shape (distance <= radius), conservatively.
[[nodiscard]] bool ball_reaches(const Ball& ball, const PlacedShape& obstacle);

[[nodiscard]] CellSet static_obstacle_cells(const CellEnvelope& envelope,
                                            const std::vector<PlacedShape>& obstacles,
                                            unsigned threads = 0,
                                            const ProgressCallback& progress = {});

}  // namespace safecell
