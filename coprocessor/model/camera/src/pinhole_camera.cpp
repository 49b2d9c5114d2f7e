#include "safecell/camera/pinhole_camera.hpp"

#include <Eigen/SVD>
#include <cmath>
#include <numbers>
#include <utility>

#include "camera_checks.hpp"
#include "error_text.hpp"
#include "safecell/camera/camera_error.hpp"

namespace safecell {
namespace {

constexpr double kMinDepthM = 1e-9;                // points nearer the camera plane do not project
constexpr double kExactRotationTolerance = 1e-12;  // rotations this close are kept as given

std::string source_of(const std::string& name) { return "camera '" + name + "'"; }

CameraFieldNames member_names() {
  return {"intrinsics.width_px",   "intrinsics.height_px",    "intrinsics.fx_px",
          "intrinsics.fy_px",      "intrinsics.cx_px",        "intrinsics.cy_px",
          "intrinsics.distortion", "cell_to_camera.rotation", "cell_to_camera.translation"};
}

Eigen::Matrix3d nearest_rotation(const Eigen::Matrix3d& rotation) {
  if (orthonormality_error(rotation) <= kExactRotationTolerance) return rotation;
  const Eigen::JacobiSVD<Eigen::Matrix3d> svd(rotation, Eigen::ComputeFullU | Eigen::ComputeFullV);
  return svd.matrixU() * svd.matrixV().transpose();
}

}  // namespace

PinholeCamera::PinholeCamera(std::string name, const CameraIntrinsics& intrinsics,
                             const Eigen::Isometry3d& cell_to_camera)
    : name_(std::move(name)),
      intrinsics_(intrinsics),
      cell_to_camera_(Eigen::Isometry3d::Identity()),
      camera_to_cell_(Eigen::Isometry3d::Identity()),
      max_radius_sq_(0.0) {
  const std::string source = source_of(name_);
  if (name_.empty()) throw_camera_error(source, "name", "empty, expected a camera name");
  check_camera_values(source, member_names(), intrinsics, cell_to_camera.linear(),
                      cell_to_camera.translation());
  cell_to_camera_.linear() = nearest_rotation(cell_to_camera.linear());
  cell_to_camera_.translation() = cell_to_camera.translation();
  camera_to_cell_ = cell_to_camera_.inverse(Eigen::Isometry);
  max_radius_sq_ = monotonic_radius_sq(intrinsics.distortion);
}

PinholeCamera PinholeCamera::look_at(std::string name, const Eigen::Vector3d& position_m,
                                     const Eigen::Vector3d& target_m, const Eigen::Vector3d& up,
                                     double horizontal_fov_rad, int width_px, int height_px) {
  const std::string source = source_of(name);
  if (!(position_m.allFinite() && target_m.allFinite() && up.allFinite())) {
    throw_camera_error(source, "look_at",
                       "position " + point_text(position_m) + ", target " + point_text(target_m) +
                           ", up " + point_text(up) + ", expected finite vectors");
  }
  const Eigen::Vector3d forward = target_m - position_m;
  if (!(forward.norm() > kMinDepthM)) {
    throw_camera_error(source, "look_at.target_m",
                       point_text(target_m) +
                           " is the camera position, expected a point away "
                           "from it");
  }
  const Eigen::Vector3d z_axis = forward.normalized();
  const Eigen::Vector3d right = z_axis.cross(up);
  if (!(right.norm() > 1e-9 * up.norm())) {
    throw_camera_error(source, "look_at.up",
                       point_text(up) + " is along the view direction " + point_text(z_axis) +
                           ", expected a direction across it");
  }
  if (!(horizontal_fov_rad > 0.0 && horizontal_fov_rad < std::numbers::pi)) {
    throw_camera_error(source, "look_at.horizontal_fov_rad",
                       number_text(horizontal_fov_rad) + ", expected an angle in (0, pi)");
  }
  // OpenCV's camera frame: x right, y down (so `up` is up in the image), z forward.
  const Eigen::Vector3d x_axis = right.normalized();
  Eigen::Matrix3d camera_to_cell_rotation;
  camera_to_cell_rotation << x_axis, z_axis.cross(x_axis), z_axis;
  Eigen::Isometry3d cell_to_camera = Eigen::Isometry3d::Identity();
  cell_to_camera.linear() = camera_to_cell_rotation.transpose();
  cell_to_camera.translation() = -(camera_to_cell_rotation.transpose() * position_m);

  CameraIntrinsics intrinsics;
  // The image spans [-0.5, width_px - 0.5): its centre is (width_px - 1) / 2, its half-width
  // width_px / 2.
  intrinsics.fx_px = 0.5 * width_px / std::tan(0.5 * horizontal_fov_rad);
  intrinsics.fy_px = intrinsics.fx_px;
  intrinsics.cx_px = 0.5 * (width_px - 1);
  intrinsics.cy_px = 0.5 * (height_px - 1);
  intrinsics.width_px = width_px;
  intrinsics.height_px = height_px;
  return PinholeCamera(std::move(name), intrinsics, cell_to_camera);
}

std::optional<Eigen::Vector2d> PinholeCamera::project(const Eigen::Vector3d& point_cell_m) const {
  const Eigen::Vector3d point = cell_to_camera_ * point_cell_m;
  if (!(point.z() > kMinDepthM)) return std::nullopt;
  const Eigen::Vector2d normalised = point.head<2>() / point.z();
  if (!(normalised.squaredNorm() <= max_radius_sq_)) return std::nullopt;
  const Eigen::Vector2d distorted = distort(intrinsics_.distortion, normalised);
  return Eigen::Vector2d(intrinsics_.fx_px * distorted.x() + intrinsics_.cx_px,
                         intrinsics_.fy_px * distorted.y() + intrinsics_.cy_px);
}

Ray PinholeCamera::back_project(const Eigen::Vector2d& pixel) const {
  const Eigen::Vector2d distorted((pixel.x() - intrinsics_.cx_px) / intrinsics_.fx_px,
                                  (pixel.y() - intrinsics_.cy_px) / intrinsics_.fy_px);
  const auto normalised = undistort(intrinsics_.distortion, distorted, max_radius_sq_);
  if (!normalised) {
    throw_camera_error(source_of(name_), "back_project",
                       "pixel " + point_text(pixel) +
                           " has no ray, expected a pixel inside the lens model's range (the "
                           "image and its surroundings)");
  }
  const Eigen::Vector3d direction_camera =
      Eigen::Vector3d(normalised->x(), normalised->y(), 1.0).normalized();
  return Ray{position_m(), camera_to_cell_.linear() * direction_camera};
}

bool PinholeCamera::in_image(const Eigen::Vector2d& pixel) const {
  return pixel.x() >= -0.5 && pixel.x() < intrinsics_.width_px - 0.5 && pixel.y() >= -0.5 &&
         pixel.y() < intrinsics_.height_px - 0.5;
}

}  // namespace safecell
