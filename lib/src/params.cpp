#include "lrchain/params.hpp"

#include <cmath>

#include "lrchain/errors.hpp"

namespace lrchain {

void validate(const Params& p) {
  if (!(std::isfinite(p.alpha) && p.alpha > 1.0))
    throw InvalidParameter("alpha", "must be a finite number > 1 (Hertz exponent; 3/2 for spheres)");
  if (!(std::isfinite(p.delta0) && p.delta0 > 0.0))
    throw InvalidParameter("delta0", "must be a finite number > 0 (precompression overlap)");
  if (!(std::isfinite(p.kappa) && p.kappa > 0.0))
    throw InvalidParameter("kappa", "must be a finite number > 0 (resonator spring constant)");
  if (!(std::isfinite(p.rho) && p.rho > 0.0))
    throw InvalidParameter("rho", "must be a finite number > 0 (mass ratio m2/m1)");
}

TaylorCoefficients taylor_coefficients(const Params& p) {
  const double a = p.alpha;
  const double d3 = std::pow(p.delta0, a - 3.0);  // one pow: delta0^(alpha-3)
  const double d2 = d3 * p.delta0;
  const double d1 = d2 * p.delta0;
  return {a * d1, -0.5 * a * (a - 1.0) * d2, a * (a - 1.0) * (a - 2.0) * d3 / 6.0};
}

double hertz_force(double r, double alpha, double delta0) {
  const double s = delta0 - r;
  const double contact = s > 0.0 ? std::pow(s, alpha) : 0.0;
  return std::pow(delta0, alpha) - contact;
}

}  // namespace lrchain
