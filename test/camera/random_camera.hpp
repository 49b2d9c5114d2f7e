#pragma once
// Random cameras for the property tests: placed anywhere around a cell, looking at a point in
// it, with moderate lens distortion, a shifted principal point and non-square pixels.

#include <Eigen/Core>
#include <cmath>
#include <numbers>
#include <random>
#include <stdexcept>
#include <string>

#include "safecell/camera/camera_error.hpp"
#include "safecell/camera/pinhole_camera.hpp"

namespace safecell::test {

inline double uniform(std::mt19937_64& rng, double lo, double hi) {
  return std::uniform_real_distribution<double>(lo, hi)(rng);
}

inline PinholeCamera random_camera(std::mt19937_64& rng, bool distorted = true,
                                   const std::string& name = "random") {
  Eigen::Vector3d position_m;
  Eigen::Vector3d target_m;
  do {
    position_m = {uniform(rng, -2.5, 2.5), uniform(rng, -2.5, 2.5), uniform(rng, 0.2, 3.0)};
    target_m = {uniform(rng, -1.0, 1.0), uniform(rng, -1.0, 1.0), uniform(rng, 0.0, 1.5)};
  } while ((target_m - position_m).norm() < 0.5 ||
           (target_m - position_m).normalized().cross(Eigen::Vector3d::UnitZ()).norm() < 0.1);
  const int width_px = static_cast<int>(uniform(rng, 160.0, 1280.0));
  const int height_px = static_cast<int>(width_px * uniform(rng, 0.5, 1.0));
  const double fov_rad = uniform(rng, 40.0, 90.0) * std::numbers::pi / 180.0;
  const PinholeCamera ideal = PinholeCamera::look_at(
      name, position_m, target_m, Eigen::Vector3d::UnitZ(), fov_rad, width_px, height_px);
  if (!distorted) return ideal;
  // Wide lenses with strong barrel distortion fold over before the image corners and are
  // refused; draw again then.
  for (int attempt = 0; attempt < 1000; ++attempt) {
    CameraIntrinsics intrinsics = ideal.intrinsics();
    intrinsics.fy_px *= uniform(rng, 0.9, 1.1);
    intrinsics.cx_px += uniform(rng, -0.05, 0.05) * width_px;
    intrinsics.cy_px += uniform(rng, -0.05, 0.05) * height_px;
    intrinsics.distortion = {uniform(rng, -0.2, 0.2), uniform(rng, -0.05, 0.05),
                             uniform(rng, -2e-3, 2e-3), uniform(rng, -2e-3, 2e-3),
                             uniform(rng, -0.01, 0.01)};
    try {
      return PinholeCamera(name, intrinsics, ideal.cell_to_camera());
    } catch (const CameraError&) {
    }
  }
  throw std::logic_error("no random distorted camera accepted in 1000 attempts");
}

}  // namespace safecell::test
