#pragma once
// The exposures of one frame set checked against each other (paper §4.5). The robot pose the
// pipeline removes is the one at the set's exposure time; a camera that exposed at another moment
// saw the robot and the people elsewhere. A known view whose exposure lies more than
// max_spread_s / 2 from the median exposure of the set's known views becomes unknown
// (CameraFault::kOutOfSync, the offset and the limit in the detail): a set whose exposures spread
// too far counts as that many unknown views, and with too few left the cycle stops.

#include <cstddef>

#include "safecell/acquisition/frame_set.hpp"

namespace safecell {

// Returns how many views it made unknown. Throws std::invalid_argument unless max_spread_s is
// finite and > 0.
std::size_t reject_out_of_sync_exposures(FrameSet& set, double max_spread_s);

// The median exposure of the set's known views (0 when none is known).
double median_exposure_s(const FrameSet& set);

}  // namespace safecell
