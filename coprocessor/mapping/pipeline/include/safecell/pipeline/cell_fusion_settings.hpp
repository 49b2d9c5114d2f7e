#pragma once
// The fusion settings a cell file asks for: its camera threshold and occlusion reach, the rest
// (sync error, padding, removal) by default. Every pipeline built from a cell starts here, so
// the service, the demo, the bench and `validate` vote the same way.

#include <string>

#include "safecell/cell/cell_model.hpp"
#include "safecell/fusion/forbidden_map_fusion.hpp"

namespace safecell {

[[nodiscard]] FusionSettings cell_fusion_settings(const CellModel& cell);

// The shortest occlusion reach, in feature cells, with which the validation found camera
// threshold 3 safe: at 3 it missed people standing against the arm, the part that collides hidden
// by the arm from two of the four cameras (docs/validation.md, "The camera threshold and the
// occlusion reach"); at 4 it missed none.
inline constexpr int kReachValidatedAtThresholdThree = 4;

// A warning, naming the cell file and its fields, when the cell votes with 3 or more cameras and
// a shorter reach than that (unset: the fusion's default, kDefaultOcclusionReach); empty when
// the vote is one the validation covers.
[[nodiscard]] std::string vote_warning(const CellModel& cell);

}  // namespace safecell
