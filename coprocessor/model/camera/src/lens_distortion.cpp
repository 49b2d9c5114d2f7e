#include "safecell/camera/lens_distortion.hpp"

#include <Eigen/LU>
#include <algorithm>
#include <cmath>
#include <limits>

namespace safecell {
namespace {

constexpr int kMaxNewtonSteps = 100;
constexpr int kMaxStepHalvings = 40;
constexpr double kConverged = 1e-15;  // residual, normalised units
constexpr double kAccepted = 1e-12;   // residual a solution may keep when steps stall

// The derivative of r * radial(r) with respect to r, as a function of s = r^2.
double radial_slope(const LensDistortion& lens, double s) {
  return 1.0 + s * (3.0 * lens.k1 + s * (5.0 * lens.k2 + s * 7.0 * lens.k3));
}

Eigen::Matrix2d jacobian(const LensDistortion& lens, const Eigen::Vector2d& point) {
  const double x = point.x();
  const double y = point.y();
  const double r2 = x * x + y * y;
  const double radial = 1.0 + r2 * (lens.k1 + r2 * (lens.k2 + r2 * lens.k3));
  const double radial_d = lens.k1 + r2 * (2.0 * lens.k2 + r2 * 3.0 * lens.k3);  // d radial / d r2
  const double cross = 2.0 * x * y * radial_d + 2.0 * lens.p1 * x + 2.0 * lens.p2 * y;
  Eigen::Matrix2d j;
  j << radial + 2.0 * x * x * radial_d + 2.0 * lens.p1 * y + 6.0 * lens.p2 * x, cross,  //
      cross, radial + 2.0 * y * y * radial_d + 6.0 * lens.p1 * y + 2.0 * lens.p2 * x;
  return j;
}

}  // namespace

Eigen::Vector2d distort(const LensDistortion& lens, const Eigen::Vector2d& point) {
  const double x = point.x();
  const double y = point.y();
  const double r2 = x * x + y * y;
  const double radial = 1.0 + r2 * (lens.k1 + r2 * (lens.k2 + r2 * lens.k3));
  return {x * radial + 2.0 * lens.p1 * x * y + lens.p2 * (r2 + 2.0 * x * x),
          y * radial + lens.p1 * (r2 + 2.0 * y * y) + 2.0 * lens.p2 * x * y};
}

std::optional<Eigen::Vector2d> undistort(const LensDistortion& lens,
                                         const Eigen::Vector2d& distorted, double max_radius_sq) {
  if (!distorted.allFinite()) return std::nullopt;
  // Damped Newton from the distorted point itself: a step is taken only when it lowers the
  // residual and stays inside the region where the model holds, else it is halved.
  Eigen::Vector2d point = distorted;
  if (point.squaredNorm() > max_radius_sq) point *= std::sqrt(max_radius_sq / point.squaredNorm());
  double residual = (distort(lens, point) - distorted).norm();
  for (int step = 0; step < kMaxNewtonSteps && residual > kConverged; ++step) {
    const Eigen::FullPivLU<Eigen::Matrix2d> lu(jacobian(lens, point));
    if (!lu.isInvertible()) break;
    Eigen::Vector2d delta = lu.solve(distort(lens, point) - distorted);
    bool improved = false;
    for (int halving = 0; halving < kMaxStepHalvings && !improved; ++halving, delta *= 0.5) {
      const Eigen::Vector2d next = point - delta;
      const double next_residual = (distort(lens, next) - distorted).norm();
      if (next.squaredNorm() <= max_radius_sq && next_residual < residual) {
        point = next;
        residual = next_residual;
        improved = true;
      }
    }
    if (!improved) break;
  }
  if (!(residual <= kAccepted)) return std::nullopt;
  return point;
}

double monotonic_radius_sq(const LensDistortion& lens) {
  // Walk s = r^2 outwards in steps of 0.1 % (at least 1e-4) until the slope turns, then bisect.
  constexpr double kLimit = 1e4;  // r = 100
  double s = 0.0;
  while (s < kLimit) {
    const double next = s + std::max(1e-4, s * 1e-3);
    if (!(radial_slope(lens, next) > 0.0)) {
      double lo = s;
      double hi = next;
      for (int i = 0; i < 100; ++i) {
        const double mid = 0.5 * (lo + hi);
        (radial_slope(lens, mid) > 0.0 ? lo : hi) = mid;
      }
      return lo;
    }
    s = next;
  }
  return std::numeric_limits<double>::infinity();
}

}  // namespace safecell
