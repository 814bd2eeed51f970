#pragma once
// sin and cos of a half wavenumber x = theta/2, |x| <= pi/2, as straight-line code (arithmetic and
// selects only), so that a loop over many wavenumbers vectorises and every path (the scalar
// coefficients, the dispersion relation, the batch loop of coefficients_batch.hpp) gets the same bits.
// Polynomials: the minimax kernels of Sun's fdlibm (k_sin.c, k_cos.c, |x| <= pi/4, error < 1 ulp);
// for pi/4 < |x| <= pi/2, sin x = cos(pi/2 - |x|) and cos x = sin(pi/2 - |x|) with pi/2 split in two
// (Cody-Waite) so that pi/2 - |x| is exact to rounding. Error <= 1 ulp against correctly rounded
// values (tests/unit/half_angle_test.cpp). Needs -ffp-contract=off for bit-identical results.
#include <bit>
#include <cmath>
#include <cstdint>

namespace lrchain::detail {

// sin(x) and cos(x) for |x| <= pi/2 (outside that range the values are not sin and cos).
inline void half_angle_sincos(double x, double& sin_x, double& cos_x) noexcept {
  constexpr double pi_over_4 = 0x1.921fb54442d18p-1;
  constexpr double pi_over_2_high = 0x1.921fb54442d18p+0;  // pi/2 rounded to double
  constexpr double pi_over_2_low = 0x1.1a62633145c07p-54;  // pi/2 - pi_over_2_high
  constexpr double S1 = -1.66666666666666324348e-01, S2 = 8.33333333332248946124e-03,
                   S3 = -1.98412698298579493134e-04, S4 = 2.75573137070700676789e-06,
                   S5 = -2.50507602534068634195e-08, S6 = 1.58969099521155010221e-10;
  constexpr double C1 = 4.16666666666666019037e-02, C2 = -1.38888888888741095749e-03,
                   C3 = 2.48015872894767294178e-05, C4 = -2.75573143513906633035e-07,
                   C5 = 2.08757232129817482790e-09, C6 = -1.13596475577881948265e-11;
  const double ax = std::abs(x);
  const bool reflect = ax > pi_over_4;
  // y + tail in [0, pi/4]: |x| itself, or pi/2 - |x| as a double plus its rounding error (the first
  // subtraction is exact by Sterbenz's lemma, the second sum is split exactly by Fast2Sum).
  const double head = reflect ? pi_over_2_high - ax : ax;
  const double y = reflect ? head + pi_over_2_low : ax;
  const double tail = reflect ? pi_over_2_low - (y - head) : 0.0;
  const double z = y * y, v = z * y;
  // fdlibm __kernel_sin(y, tail): y + y^3 (S1 + z (S2 + ... + z^4 S6)) + the tail's first-order term.
  const double rs = S2 + z * (S3 + z * (S4 + z * (S5 + z * S6)));
  const double sin_y = y - ((z * (0.5 * tail - v * rs) - tail) - v * S1);
  // fdlibm __kernel_cos(y, tail): 1 - (z/2 - (z r - y tail)); for y >= 0.3 the 1 is split as
  // (1 - qy) - (z/2 - qy - ...) with qy = y/4 cut to 32 bits (0.28125 above 0.78125) so that the
  // subtraction stays exact.
  const double rc = z * (C1 + z * (C2 + z * (C3 + z * (C4 + z * (C5 + z * C6)))));
  const double quarter = std::bit_cast<double>(std::bit_cast<std::uint64_t>(0.25 * y) & 0xffffffff00000000ull);
  const double qy = y < 0.3 ? 0.0 : y > 0.78125 ? 0.28125 : quarter;
  const double cos_y = (1.0 - qy) - ((0.5 * z - qy) - (z * rc - y * tail));
  sin_x = std::copysign(reflect ? cos_y : sin_y, x);
  cos_x = reflect ? sin_y : cos_y;
}

}  // namespace lrchain::detail
