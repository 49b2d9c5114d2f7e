#pragma once
// Why a cell of a forbidden map was forbidden: the answer to "why did the robot stop here?".
// A cell is forbidden because it is static (a static obstacle of the cell file, or a blind spot
// the tables forbid), because the whole map was forbidden (the robot's pose unknown, ...), or
// because it was critical: for some robot part, enough cameras suspected it. For a critical cell
// the explanation names, per part, each camera that voted and the feature cells whose LUT-2 entry
// holds the cell - the obstacle pixels (and, with hidden votes, the robot's pixels) that made it
// suspicious - read from the same tables and views the fusion used.

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "safecell/camera/feature_grid.hpp"
#include "safecell/explain/fused_views.hpp"
#include "safecell/fusion/forbidden_map_fusion.hpp"

namespace safecell {

struct CameraVote {
  std::size_t camera = 0;
  bool unknown = false;  // the view was unknown: it suspects every cell it can see
  std::vector<FeatureCell> obstacle_cells;  // obstacle feature cells that mark the cell
  std::vector<FeatureCell> hidden_cells;    // robot feature cells that vote as hidden
};

struct PartVote {
  std::size_t part = 0;
  std::vector<CameraVote> cameras;  // the cameras that voted for the cell through this part
  int seeing = 0;                   // of them, those with obstacle cells or unknown views
  bool critical = false;            // the part's vote made the cell critical
};

enum class ForbiddenBecause {
  kCritical,      // see `parts`
  kStatic,        // a static obstacle or a blind spot (the tables' static cells)
  kAllForbidden,  // the whole map was forbidden (see all_forbidden)
  kNotForbidden,  // the map was not forbidden there
  kMapUnknown,    // the map is older than the kept views, or was never sent
};

const char* to_string(ForbiddenBecause because);

struct CellExplanation {
  CellIndex cell = 0;
  std::uint64_t map_version = 0;
  ForbiddenBecause because = ForbiddenBecause::kMapUnknown;
  bool also_static = false;     // critical and static both
  std::string all_forbidden;    // for kAllForbidden
  std::vector<PartVote> parts;  // every part some camera voted for the cell through
};

// Explains `cell` of the map whose views are `views` (nullptr: unknown), from the tables and
// settings of `fusion`. Throws std::out_of_range for a cell outside the grid, and
// std::invalid_argument for views of another camera count.
CellExplanation explain_cell(const ForbiddenMapFusion& fusion, const FusedViews* views,
                             CellIndex cell);

// One line for logs and the status: the cell, the map, why; for a critical cell each critical
// part with its cameras (by name) and up to `cells_per_camera` feature cells each.
std::string describe(const CellExplanation& explanation, const ForbiddenMapFusion& fusion,
                     std::size_t cells_per_camera = 4);

}  // namespace safecell
