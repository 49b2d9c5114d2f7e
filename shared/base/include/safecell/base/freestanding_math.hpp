#pragma once
// The few math functions the freestanding core needs, written with +, -, *, / only, so they give
// identical bits on every IEEE-754 target (with -ffp-contract=off) and need no hosted libm.

#include <cstdint>

namespace safecell {

inline constexpr double kPi = 3.14159265358979323846;

constexpr bool is_finite(double value) noexcept {
  // NaN fails the first comparison, +-infinity the second.
  return value == value && value - value == 0.0;
}

constexpr bool is_finite_non_negative(double value) noexcept {
  return is_finite(value) && value >= 0.0;
}

constexpr double infinity() noexcept { return __builtin_inf(); }

// Sine of an angle in [-pi/2, pi/2] (radians); outside that range the result is inaccurate.
double sin_small_rad(double angle_rad) noexcept;

// Arc sine in radians of x in [-1, 1], accurate to a few ulp. Precondition: |x| <= 1 (callers
// validate; an argument outside returns NaN).
double asin_rad(double x) noexcept;

// Square root of a finite x >= 0 by Newton's method, to within an ulp or two; NaN otherwise.
double sqrt_of(double x) noexcept;

// Smallest integer >= value, for finite value in [0, 2^53]. Precondition checked by callers.
std::uint64_t ceil_to_u64(double value) noexcept;

}  // namespace safecell
