// half_angle_sincos (lrchain/half_angle.hpp): sin and cos of theta/2 within 1 ulp of the correctly
// rounded values. Reference: glibc's sinl/cosl in x87 extended precision (64-bit significand, 11 bits
// more than double), so the reference's own error is below 1/1000 ulp of a double.
#include <doctest/doctest.h>

#include <cmath>
#include <numbers>
#include <random>

#include "lrchain/half_angle.hpp"

namespace {

// |value - reference| in units of the last place of the reference rounded to double.
double ulp_error(double value, long double reference) {
  const double rounded = static_cast<double>(reference);
  const double ulp = std::nextafter(std::abs(rounded), INFINITY) - std::abs(rounded);
  return static_cast<double>(std::abs(static_cast<long double>(value) - reference) / ulp);
}

}  // namespace

TEST_CASE("half_angle_sincos is within 1 ulp of sin and cos on [-pi/2, pi/2]") {
  std::mt19937_64 random(20261123);
  std::uniform_real_distribution<double> wavenumber(-std::numbers::pi, std::numbers::pi);
  double worst_sin = 0, worst_cos = 0;
  for (int i = 0; i < 400000; ++i) {
    // every 4th point near the ends and the switch at pi/4, where the reduction matters most
    const double theta = i % 4 ? wavenumber(random)
                               : (i % 8 ? std::numbers::pi : std::numbers::pi / 2) * (1.0 - 1e-9 * (i / 4 % 1000));
    const double x = 0.5 * theta;
    double s, c;
    lrchain::detail::half_angle_sincos(x, s, c);
    worst_sin = std::max(worst_sin, ulp_error(s, std::sin(static_cast<long double>(x))));
    worst_cos = std::max(worst_cos, ulp_error(c, std::cos(static_cast<long double>(x))));
  }
  MESSAGE("worst error: sin " << worst_sin << " ulp, cos " << worst_cos << " ulp");
  CHECK(worst_sin < 1.0);
  CHECK(worst_cos < 1.0);
}

TEST_CASE("half_angle_sincos is exact at 0 and odd in x, and its values at pi/2 are the doubles nearest") {
  double s, c;
  lrchain::detail::half_angle_sincos(0.0, s, c);
  CHECK(s == 0.0);
  CHECK(c == 1.0);
  lrchain::detail::half_angle_sincos(-0.0, s, c);
  CHECK(std::signbit(s));
  // x = pi/2 rounded: sin x = 1 and cos x = pi/2 - x = 6.123233995736766e-17 (both correctly rounded).
  lrchain::detail::half_angle_sincos(0.5 * std::numbers::pi, s, c);
  CHECK(s == 1.0);
  CHECK(c == doctest::Approx(6.123233995736766e-17).epsilon(1e-15));
  double s_negative, c_negative;
  for (double x : {0.1, 0.3, 0.5, 0.785, 0.79, 1.2, 1.57}) {
    lrchain::detail::half_angle_sincos(x, s, c);
    lrchain::detail::half_angle_sincos(-x, s_negative, c_negative);
    CHECK(s_negative == -s);
    CHECK(c_negative == c);
  }
}
