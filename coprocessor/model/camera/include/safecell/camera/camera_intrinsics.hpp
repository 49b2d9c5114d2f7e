#pragma once
// The intrinsic parameters of one camera in OpenCV's model. Pixel coordinates follow OpenCV:
// the centre of the top-left pixel is (0, 0), u grows to the right and v downwards, and the
// image covers [-0.5, width_px - 0.5) x [-0.5, height_px - 0.5).

#include "safecell/camera/lens_distortion.hpp"

namespace safecell {

struct CameraIntrinsics {
  double fx_px = 0.0;  // focal lengths in pixels
  double fy_px = 0.0;
  double cx_px = 0.0;  // principal point in pixels
  double cy_px = 0.0;
  LensDistortion distortion;
  int width_px = 0;
  int height_px = 0;

  friend bool operator==(const CameraIntrinsics&, const CameraIntrinsics&) = default;
};

}  // namespace safecell
