#pragma once
// The entries of a cell (cell_config.hpp) and the room the robot keeps from them. A person is
// first seen when they step through an entry; from then on the system needs the response time
// to command a stop and the robot its stopping time, while the person walks on. So, as ISO 13855
// asks of any detection zone's boundary, the robot must stay the separation distance
// S = K * (t_response + t_stop) + C away from every entry: the C-space cells whose envelope comes
// within S of an entry are static obstacle cells, as blind spots are.

#include <Eigen/Core>
#include <vector>

#include "safecell/cell/cell_config.hpp"
#include "safecell/cell/cell_model.hpp"
#include "safecell/geometry/shape.hpp"

namespace safecell {

// S in metres.
[[nodiscard]] double separation_distance_m(const SeparationDistanceConfig& separation);

// Per entry, the volume within S of its opening, inside the cell, floor to ceiling: a box S deep
// from the wall and S wider than the opening on each side (clipped to the cell). Empty when the
// cell names no entries.
[[nodiscard]] std::vector<PlacedShape> entry_zone_volumes(const CellConfig& cell);

// The cell the tables are built from: `cell` with the entry zones as further static obstacles.
[[nodiscard]] CellModel with_entry_zones_forbidden(const CellModel& cell);

// A floor point at an entry: `along` in [0, 1] across its opening, `inward_m` from the wall into
// the cell (negative: outside it).
[[nodiscard]] Eigen::Vector2d entry_floor_point(const CellConfig& cell, const EntryConfig& entry,
                                                double along, double inward_m);

}  // namespace safecell
