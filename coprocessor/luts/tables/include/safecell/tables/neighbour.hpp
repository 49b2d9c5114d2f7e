#pragma once
// The neighbours LUT-2 entries are stored against (pixel_table_builder.hpp, "differences"): the
// entry on the left and the one above, of the same pyramid level. An index into the difference
// tables of PixelTables and CameraLuts.

#include <cstddef>

namespace safecell {

enum Neighbour : std::size_t { kLeftNeighbour = 0, kUpperNeighbour = 1, kNeighbourCount = 2 };

}  // namespace safecell
