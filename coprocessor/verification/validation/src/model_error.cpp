#include "safecell/validation/model_error.hpp"

#include <cmath>
#include <numbers>
#include <random>
#include <stdexcept>
#include <string>

#include "safecell/camera/camera_error.hpp"
#include "safecell/geometry/grown_shape.hpp"

namespace safecell {
namespace {

void check_bound(const char* name, double value, double limit) {
  if (!(std::abs(value) <= limit)) {
    throw std::invalid_argument(std::string("model error ") + name + ": " + std::to_string(value) +
                                ", expected at most " + std::to_string(limit) + " in size");
  }
}

void check(const ModelError& error) {
  check_bound("camera rotation (deg)", error.camera_rotation_deg, 10.0);
  check_bound("camera translation (m)", error.camera_translation_m, 0.5);
  check_bound("focal error", error.focal_error, 0.2);
  check_bound("lens k1", error.lens_k1, 0.5);
  check_bound("robot growth (m)", error.robot_growth_m, 0.2);
  if (error.camera_rotation_deg < 0.0 || error.camera_translation_m < 0.0 ||
      error.focal_error < 0.0 || error.robot_growth_m < 0.0) {
    throw std::invalid_argument(
        "model error: rotation, translation, focal error and growth are "
        "sizes, expected >= 0");
  }
}

Eigen::Vector3d random_unit(std::mt19937_64& rng) {
  std::normal_distribution<double> gauss;
  Eigen::Vector3d v(gauss(rng), gauss(rng), gauss(rng));
  while (v.norm() < 1e-9) v = Eigen::Vector3d(gauss(rng), gauss(rng), gauss(rng));
  return v.normalized();
}

PinholeCamera camera_with_error(const PinholeCamera& camera, const ModelError& error,
                                std::mt19937_64& rng) {
  CameraIntrinsics intrinsics = camera.intrinsics();
  const double sign = std::bernoulli_distribution(0.5)(rng) ? 1.0 : -1.0;
  intrinsics.fx_px *= 1.0 + sign * error.focal_error;
  intrinsics.fy_px *= 1.0 + sign * error.focal_error;
  intrinsics.distortion.k1 += error.lens_k1;
  // Turned about its own optical centre, then moved.
  Eigen::Isometry3d camera_to_cell = camera.camera_to_cell();
  camera_to_cell.linear() =
      Eigen::AngleAxisd(error.camera_rotation_deg * std::numbers::pi / 180.0, random_unit(rng))
          .toRotationMatrix() *
      camera_to_cell.linear();
  camera_to_cell.translation() += error.camera_translation_m * random_unit(rng);
  return PinholeCamera(camera.name(), intrinsics, camera_to_cell.inverse());
}

}  // namespace

CellModel world_with_error(const CellModel& cell, const ModelError& error, std::uint64_t seed) {
  check(error);
  CellModel world = cell;
  if (!error.any()) return world;
  std::mt19937_64 rng(seed ^ 0x6D6F64656C657272ull);  // "modelerr"
  for (auto& camera : world.cameras) {
    try {
      camera = camera_with_error(camera, error, rng);
    } catch (const CameraError& bad) {
      throw std::invalid_argument(std::string("model error makes an impossible camera: ") +
                                  bad.what());
    }
  }
  if (error.robot_growth_m > 0.0) {
    if (!world.robot) throw std::invalid_argument("model error: the cell has no robot to grow");
    for (auto& shape : world.robot->base.collision) shape = grown_by(shape, error.robot_growth_m);
    for (auto& link : world.robot->links) {
      for (auto& shape : link.collision) shape = grown_by(shape, error.robot_growth_m);
    }
  }
  return world;
}

}  // namespace safecell
