#pragma once
// The paper's camera set-up: four 704 x 576 px grayscale cameras in the top corners of a
// 4 m x 4 m x 3 m cell, all looking at a point 0.8 m above the robot base.

#include <vector>

#include "safecell/camera/pinhole_camera.hpp"

namespace safecell {

inline constexpr int kDefaultCameraWidthPx = 704;
inline constexpr int kDefaultCameraHeightPx = 576;
inline constexpr double kDefaultCameraHorizontalFovDeg = 75.0;

// "cam0".."cam3" at (+1.95, +1.95), (-1.95, +1.95), (-1.95, -1.95), (+1.95, -1.95) m, 2.9 m up,
// looking at (0, 0, 0.8) m with +z up in the image; no lens distortion.
[[nodiscard]] std::vector<PinholeCamera> default_cameras();

}  // namespace safecell
