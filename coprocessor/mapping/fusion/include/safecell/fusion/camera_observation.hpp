#pragma once
// What one camera says in one cycle: its blocked feature cells, or that its view is unknown
// (a camera fault, a missing frame). An unknown view marks every cell the camera could see.

#include "safecell/features/feature_mask.hpp"

namespace safecell {

struct CameraObservation {
  bool known = false;
  FeatureMask blocked;  // the difference image; only read when known
};

}  // namespace safecell
