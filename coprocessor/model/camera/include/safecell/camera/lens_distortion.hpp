#pragma once
// OpenCV's five-coefficient lens model (radial k1, k2, k3; tangential p1, p2) on normalised image
// coordinates (x, y) = (X / Z, Y / Z) in the camera frame:
//   r^2 = x^2 + y^2,  radial = 1 + k1 r^2 + k2 r^4 + k3 r^6
//   x_d = x radial + 2 p1 x y + p2 (r^2 + 2 x^2)
//   y_d = y radial + p1 (r^2 + 2 y^2) + 2 p2 x y
// The polynomial only describes a real lens while it grows with r: past its first turning point
// it folds back, and a point far outside the view would land inside the image. The model is
// therefore used only up to monotonic_radius_sq().

#include <Eigen/Core>
#include <optional>

namespace safecell {

struct LensDistortion {
  double k1 = 0.0;
  double k2 = 0.0;
  double p1 = 0.0;
  double p2 = 0.0;
  double k3 = 0.0;

  friend bool operator==(const LensDistortion&, const LensDistortion&) = default;
};

// Undistorted normalised coordinates -> distorted normalised coordinates.
[[nodiscard]] Eigen::Vector2d distort(const LensDistortion& lens, const Eigen::Vector2d& point);

// The inverse of distort() by damped Newton iteration, to about 1e-15. nullopt when no
// undistorted point with r^2 <= max_radius_sq maps onto `distorted` (or it is not finite).
[[nodiscard]] std::optional<Eigen::Vector2d> undistort(const LensDistortion& lens,
                                                       const Eigen::Vector2d& distorted,
                                                       double max_radius_sq);

// r^2 at the first turning point of the radial mapping r -> r radial(r), that is the first
// root of 1 + 3 k1 r^2 + 5 k2 r^4 + 7 k3 r^6; +infinity when it keeps growing up to r = 100
// (89.4 degrees off the optical axis). The tangential terms are left out of this bound.
[[nodiscard]] double monotonic_radius_sq(const LensDistortion& lens);

}  // namespace safecell
