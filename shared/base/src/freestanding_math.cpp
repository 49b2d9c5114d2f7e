#include "safecell/base/freestanding_math.hpp"

namespace safecell {
namespace {

// Taylor series of sine and cosine; 14 terms bring the truncation error below 1e-20 on
// [-pi/2, pi/2].
constexpr int kSeriesTerms = 14;

double cos_small_rad(double angle_rad) noexcept {
  const double square = angle_rad * angle_rad;
  double term = 1.0;
  double sum = 1.0;
  for (int k = 1; k <= kSeriesTerms; ++k) {
    term *= -square / static_cast<double>((2 * k - 1) * (2 * k));
    sum += term;
  }
  return sum;
}

}  // namespace

double sin_small_rad(double angle_rad) noexcept {
  const double square = angle_rad * angle_rad;
  double term = angle_rad;
  double sum = angle_rad;
  for (int k = 1; k <= kSeriesTerms; ++k) {
    term *= -square / static_cast<double>((2 * k) * (2 * k + 1));
    sum += term;
  }
  return sum;
}

double asin_rad(double x) noexcept {
  if (!(x >= -1.0 && x <= 1.0)) return __builtin_nan("");
  if (x < 0.0) return -asin_rad(-x);
  if (x == 1.0) return kPi / 2.0;
  // Newton's method on f(y) = sin(y) - x. f is increasing and concave on [0, pi/2] and
  // asin(x) >= x, so starting at y = x every step stays below the root and moves towards it:
  // the iteration cannot overshoot, and it stops when a step no longer makes progress.
  double y = x;
  for (int iteration = 0; iteration < 100; ++iteration) {
    const double step = (sin_small_rad(y) - x) / cos_small_rad(y);
    const double next = y - step;
    if (!(next > y)) break;
    y = next;
  }
  return y;
}

std::uint64_t ceil_to_u64(double value) noexcept {
  auto truncated = static_cast<std::uint64_t>(value);
  if (static_cast<double>(truncated) < value) ++truncated;
  return truncated;
}

double sqrt_of(double x) noexcept {
  if (!is_finite_non_negative(x)) return __builtin_nan("");
  if (x == 0.0) return 0.0;
  // Scale x into [1, 4) by powers of 4 so Newton starts close and converges in a few steps.
  double scale = 1.0;
  double y = x;
  for (int i = 0; i < 1100 && y >= 4.0; ++i) {
    y *= 0.25;
    scale *= 2.0;
  }
  for (int i = 0; i < 1100 && y < 1.0; ++i) {
    y *= 4.0;
    scale *= 0.5;
  }
  double root = (y + 1.0) * 0.5;  // >= sqrt(y): Newton then decreases monotonically
  for (int i = 0; i < 8; ++i) root = 0.5 * (root + y / root);
  return root * scale;
}

}  // namespace safecell
