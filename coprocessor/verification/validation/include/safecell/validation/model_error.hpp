#pragma once
// Model error for validation (../shared/VALIDATION.md): the simulated world differs from the
// model the tables were built from, as a real cell does. Applied to the rendered world and the
// ground truth, never to the model: each camera is turned by `camera_rotation_deg` about a random
// axis, moved by `camera_translation_m` in a random direction and its focal length scaled by
// 1 +- `focal_error` (each at its bound, the worst case, with a random sign); its lens gets radial
// distortion `lens_k1` the model does not know; and the robot's every collision shape is
// `robot_growth_m` larger (cables, tolerances). The padding of the tables and of robot removal
// is what must cover these.

#include <cstdint>

#include "safecell/cell/cell_model.hpp"

namespace safecell {

struct ModelError {
  double camera_rotation_deg = 0.0;
  double camera_translation_m = 0.0;
  double focal_error = 0.0;  // a fraction: 0.01 is 1 %
  double lens_k1 = 0.0;
  double robot_growth_m = 0.0;

  [[nodiscard]] bool any() const {
    return camera_rotation_deg != 0.0 || camera_translation_m != 0.0 || focal_error != 0.0 ||
           lens_k1 != 0.0 || robot_growth_m != 0.0;
  }
};

// The tolerances the default padding (2 cm) is documented to cover (docs/validation.md).
inline constexpr ModelError kDocumentedTolerances{0.5, 0.01, 0.01, -0.02, 0.005};

// The real world of `cell` under `error`: cameras and robot changed as above, drawn with `seed`.
// Throws std::invalid_argument for a negative or absurd error (rotation above 10 deg,
// translation above 0.5 m, focal error above 0.2, |k1| above 0.5, growth above 0.2 m), a lens
// that folds the image over, or a cell without a robot model when the robot grows.
[[nodiscard]] CellModel world_with_error(const CellModel& cell, const ModelError& error,
                                         std::uint64_t seed);

}  // namespace safecell
