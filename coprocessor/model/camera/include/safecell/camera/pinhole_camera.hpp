#pragma once
// One stationary camera: OpenCV's pinhole model with lens distortion, placed in the cell.
//
// Frames. The cell frame has z up, in metres, with the floor centre (the robot base) at the
// origin. The camera frame is OpenCV's: z forward along the optical axis, x right, y down.
// cell_to_camera maps cell points into the camera frame: x_camera = cell_to_camera * x_cell.
// Pixels follow OpenCV's convention (see camera_intrinsics.hpp): integer coordinates are pixel
// centres.
//
// Objects are immutable after construction and safe to share between threads.

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <optional>
#include <string>

#include "safecell/camera/camera_intrinsics.hpp"

namespace safecell {

// A half-line in the cell frame; `direction` has unit length.
struct Ray {
  Eigen::Vector3d origin_m;
  Eigen::Vector3d direction;

  [[nodiscard]] Eigen::Vector3d point_at(double distance_m) const {
    return origin_m + distance_m * direction;
  }
};

class PinholeCamera {
 public:
  // Throws CameraError (source "camera '<name>'") unless: the name is not empty; the image size
  // is positive; fx_px and fy_px are finite and > 0; the principal point, the distortion
  // coefficients and the translation are finite; the rotation is orthonormal with determinant +1
  // to 1e-6 (it is then made exactly orthonormal); and the lens model is monotonic out to the
  // image corners, so every pixel of the image has exactly one ray.
  PinholeCamera(std::string name, const CameraIntrinsics& intrinsics,
                const Eigen::Isometry3d& cell_to_camera);

  // A camera at `position_m` whose optical axis passes through `target_m`, rolled so that `up`
  // (usually +z) points up in the image; square pixels, no distortion, the principal point at
  // the image centre ((width_px - 1) / 2, (height_px - 1) / 2), and the image edges at
  // +-horizontal_fov_rad / 2. Throws CameraError for coincident points, `up` along the view
  // direction, or a field of view outside (0, pi).
  static PinholeCamera look_at(std::string name, const Eigen::Vector3d& position_m,
                               const Eigen::Vector3d& target_m, const Eigen::Vector3d& up,
                               double horizontal_fov_rad, int width_px, int height_px);

  [[nodiscard]] const std::string& name() const { return name_; }
  [[nodiscard]] const CameraIntrinsics& intrinsics() const { return intrinsics_; }
  [[nodiscard]] const Eigen::Isometry3d& cell_to_camera() const { return cell_to_camera_; }
  [[nodiscard]] const Eigen::Isometry3d& camera_to_cell() const { return camera_to_cell_; }
  // The optical centre in the cell frame.
  [[nodiscard]] Eigen::Vector3d position_m() const { return camera_to_cell_.translation(); }

  // Pixel coordinates of a cell point, distortion applied; they may lie outside the image (see
  // in_image()). nullopt when the point is on or behind the camera plane (z_camera <= 1e-9 m),
  // or so far off the axis that the lens model no longer holds there.
  [[nodiscard]] std::optional<Eigen::Vector2d> project(const Eigen::Vector3d& point_cell_m) const;

  // The ray of cell points that project() maps onto `pixel`, from the optical centre. Every
  // pixel inside the image has one; throws CameraError for a pixel far outside it beyond the
  // lens model's range, or one that is not finite.
  [[nodiscard]] Ray back_project(const Eigen::Vector2d& pixel) const;

  // Whether the pixel coordinates fall on the image: [-0.5, width) x [-0.5, height) minus 0.5.
  [[nodiscard]] bool in_image(const Eigen::Vector2d& pixel) const;

 private:
  std::string name_;
  CameraIntrinsics intrinsics_;
  Eigen::Isometry3d cell_to_camera_;
  Eigen::Isometry3d camera_to_cell_;
  double max_radius_sq_;  // the lens model holds for normalised r^2 up to this
};

}  // namespace safecell
