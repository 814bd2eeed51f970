#include "lrchain/coefficients.hpp"

#include <cmath>
#include <numbers>

#include "lrchain/errors.hpp"
#include "lrchain/half_angle.hpp"
#include "coefficients_kernel.hpp"

namespace lrchain {

std::string_view to_string(Regime r) {
  switch (r) {
    case Regime::focusing: return "focusing";
    case Regime::defocusing: return "defocusing";
    case Regime::degenerate: return "degenerate";
    case Regime::singular: return "singular";
  }
  return "singular";
}

// The shared straight-line evaluation (coefficients_kernel.hpp) at sin(theta/2), cos(theta/2).
NlsCoefficients coefficients_unchecked(const Params& p, const TaylorCoefficients& K, Branch b, double theta) {
  double sh, ch;
  detail::half_angle_sincos(0.5 * theta, sh, ch);
  return b == Branch::optical ? detail::coefficients_from_half_angle<Branch::optical>(p, K, theta, sh, ch)
                              : detail::coefficients_from_half_angle<Branch::acoustic>(p, K, theta, sh, ch);
}

void check_resonant_chain_wavenumber(Branch b, double theta) {
  if (!(std::isfinite(theta) && theta > -std::numbers::pi && theta <= std::numbers::pi))
    throw InvalidParameter("theta", "must be a wavenumber in (-pi, pi]");
  if (b == Branch::acoustic && theta == 0.0)
    throw InvalidParameter("theta", "must be nonzero on the acoustic branch (theta = 0 is the zero-frequency mode); "
                                    "valid range (-pi, 0) U (0, pi]");
}

NlsCoefficients coefficients(const Params& p, Branch b, double theta) {
  validate(p);
  check_resonant_chain_wavenumber(b, theta);
  return coefficients_unchecked(p, taylor_coefficients(p), b, theta);
}

}  // namespace lrchain
