#include "camera_checks.hpp"

#include <Eigen/LU>
#include <array>
#include <cmath>

#include "error_text.hpp"
#include "safecell/camera/camera_error.hpp"

namespace safecell {
namespace {

// Calibration files written with fewer digits stay usable; the rotation is then re-orthonormalised.
constexpr double kRotationTolerance = 1e-6;
// Bounds beyond any camera of a robot cell, so that a value off by powers of ten is refused:
// sensors up to 32,768 px a side; radial terms of wide-angle fits stay within tens, tangential
// ones within hundredths; a translation within 1e6 of the file's units (metres here, millimetres
// in MC-Calib's files; where a camera may stand in its cell is the cell's check).
constexpr int kMaxImageSide_px = 32768;
constexpr double kMaxRadialTerm = 1e3;
constexpr double kMaxTangentialTerm = 1.0;
constexpr double kMaxTranslation = 1e6;

void check_size(const std::string& source, const std::string& field, int size_px) {
  if (size_px <= 0 || size_px > kMaxImageSide_px) {
    throw_camera_error(source, field,
                       std::to_string(size_px) + " px, expected a whole number of pixels in 1.." +
                           std::to_string(kMaxImageSide_px));
  }
}

void check_focal_length(const std::string& source, const std::string& field, double value_px) {
  if (!(std::isfinite(value_px) && value_px > 0.0)) {
    throw_camera_error(source, field,
                       number_text(value_px) + ", expected a finite focal length in pixels > 0");
  }
}

void check_finite(const std::string& source, const std::string& field, double value) {
  if (!std::isfinite(value)) {
    throw_camera_error(source, field, number_text(value) + ", expected a finite number");
  }
}

void check_within(const std::string& source, const std::string& field, double value, double bound,
                  const char* unit) {
  check_finite(source, field, value);
  if (std::abs(value) > bound) {
    throw_camera_error(
        source, field,
        number_text(value) + ", expected a value within +-" + number_text(bound) + unit);
  }
}

void check_rotation(const std::string& source, const std::string& field,
                    const Eigen::Matrix3d& rotation) {
  if (!rotation.allFinite()) {
    throw_camera_error(source, field,
                       matrix_text(rotation) + " is not finite, expected a rotation matrix");
  }
  const double error = orthonormality_error(rotation);
  if (error > kRotationTolerance || rotation.determinant() < 0.0) {
    throw_camera_error(source, field,
                       matrix_text(rotation) + " is not a rotation (max |R^T R - I| = " +
                           number_text(error) + ", det = " + number_text(rotation.determinant()) +
                           "), expected an orthonormal matrix with determinant +1");
  }
}

// Every pixel must have one ray: the image corners, the farthest pixels from the principal
// point, must come from inside the region where the lens model grows monotonically.
void check_lens_covers_image(const std::string& source, const std::string& field,
                             const CameraIntrinsics& in) {
  const double max_radius_sq = monotonic_radius_sq(in.distortion);
  const double right = in.width_px - 0.5;
  const double bottom = in.height_px - 0.5;
  const std::array<Eigen::Vector2d, 4> corners = {
      Eigen::Vector2d(-0.5, -0.5), {right, -0.5}, {-0.5, bottom}, {right, bottom}};
  for (const Eigen::Vector2d& corner : corners) {
    const Eigen::Vector2d normalised((corner.x() - in.cx_px) / in.fx_px,
                                     (corner.y() - in.cy_px) / in.fy_px);
    if (!undistort(in.distortion, normalised, max_radius_sq)) {
      const LensDistortion& d = in.distortion;
      throw_camera_error(
          source, field,
          "[" + number_text(d.k1) + ", " + number_text(d.k2) + ", " + number_text(d.p1) + ", " +
              number_text(d.p2) + ", " + number_text(d.k3) +
              "] fold the image over before its corner pixel " + point_text(corner) +
              ", expected a lens model that grows monotonically out to the image corners");
    }
  }
}

}  // namespace

double orthonormality_error(const Eigen::Matrix3d& rotation) {
  return (rotation.transpose() * rotation - Eigen::Matrix3d::Identity()).cwiseAbs().maxCoeff();
}

void check_camera_values(const std::string& source, const CameraFieldNames& names,
                         const CameraIntrinsics& intrinsics, const Eigen::Matrix3d& rotation,
                         const Eigen::Vector3d& translation_m) {
  check_size(source, names.width, intrinsics.width_px);
  check_size(source, names.height, intrinsics.height_px);
  check_focal_length(source, names.fx, intrinsics.fx_px);
  check_focal_length(source, names.fy, intrinsics.fy_px);
  check_finite(source, names.cx, intrinsics.cx_px);
  check_finite(source, names.cy, intrinsics.cy_px);
  const LensDistortion& d = intrinsics.distortion;
  for (const double k : {d.k1, d.k2, d.k3}) {
    check_within(source, names.distortion, k, kMaxRadialTerm, " (a radial term k)");
  }
  for (const double p : {d.p1, d.p2}) {
    check_within(source, names.distortion, p, kMaxTangentialTerm, " (a tangential term p)");
  }
  check_rotation(source, names.rotation, rotation);
  for (const double t : translation_m) {
    check_within(source, names.translation, t, kMaxTranslation, "");
  }
  check_lens_covers_image(source, names.distortion, intrinsics);
}

}  // namespace safecell
