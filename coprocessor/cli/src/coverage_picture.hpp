#pragma once
// The floor plan of a cell's camera coverage (floor_coverage.hpp), for `safecell cell coverage`
// and the demo's report: per floor position the cameras that see a person standing there (red:
// a blind spot), the walls, the static obstacles, the robot's reach and the cameras.
// Private to the CLI.

#include <opencv2/core/mat.hpp>

#include "safecell/cell/cell_model.hpp"
#include "safecell/validation/floor_coverage.hpp"

namespace safecell {

// CV_8UC3, 150 pixels per metre, with a legend.
[[nodiscard]] cv::Mat floor_plan(const CellModel& cell, const FloorCoverage& coverage);

}  // namespace safecell
