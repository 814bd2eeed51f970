#include "lrchain/coefficients.hpp"

#include <cmath>
#include <limits>
#include <numbers>

#include "lrchain/errors.hpp"
#include "lrchain/generated/nls_coefficients.hpp"

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

// Coefficients of (eq:mod1)-(eq:NLS) from the generated evaluators; omega from (eq:disp1d).
NlsCoefficients coefficients_unchecked(const Params& p, const TaylorCoefficients& K, Branch b, double theta) {
  const double sh = std::sin(0.5 * theta), ch = std::cos(0.5 * theta);
  const double D1 = 4.0 * sh * sh;  // 4 sin^2(theta/2), no cancellation near theta = 0
  const double sigma = 2.0 * sh * ch;
  // (eq:disp1d) in the cancellation-free form of dispersion_omega().
  const double D = K.K2 * D1, kr = p.kappa / p.rho;
  const double m = D + p.kappa - kr;
  const double upper = 0.5 * (D + p.kappa + kr + std::sqrt(m * m + 4.0 * p.kappa * kr));
  const double omega = b == Branch::optical ? std::sqrt(upper) : std::sqrt(D * kr / upper);
  // mu = rho omega^2 - kappa, the root of mu^2 - B mu - rho kappa^2 = 0 (det M = 0 rewritten),
  // B = rho (D + kappa) - kappa; positive root on the optical branch, negative on the acoustic one,
  // each taken in the form without cancellation.
  const double B = p.rho * (D + p.kappa) - p.kappa;
  const double disc = std::sqrt(B * B + 4.0 * p.rho * p.kappa * p.kappa);
  const double rk2 = 2.0 * p.rho * p.kappa * p.kappa;
  const double mu = b == Branch::optical ? (B >= 0.0 ? 0.5 * (B + disc) : rk2 / (disc - B))
                                         : (B <= 0.0 ? 0.5 * (B - disc) : -rk2 / (B + disc));

  const generated::NlsValues v = generated::resonant_chain_nls(D1, sigma, omega, K.K2, K.K3, K.K4, p.kappa, p.rho, mu);
  NlsCoefficients c;
  c.theta = theta;
  c.omega = omega;
  c.group_velocity = v.group_velocity;
  c.curvature = v.curvature;
  c.gamma = v.gamma;
  c.beta = v.beta;
  c.nonresonance1 = v.nonresonance1;
  c.nonresonance2 = v.nonresonance2;
  c.h_tilde_numerator = v.h_tilde_numerator;
  // Violation test relative to the size of the terms of each non-resonance value.
  const double w2 = omega * omega;
  const double scale1 = (4.0 * w2 + 4.0 * K.K2 * sigma * sigma + p.kappa) * (p.kappa + 4.0 * w2 * p.rho) + p.kappa * p.kappa;
  const double scale2 = v.group_velocity * v.group_velocity * (1.0 + p.rho) + K.K2;
  if (std::abs(v.nonresonance1) <= kNonresonanceTolerance * scale1 ||
      std::abs(v.nonresonance2) <= kNonresonanceTolerance * scale2) {
    const double nan = std::numeric_limits<double>::quiet_NaN();
    c.h = c.lambda = c.h_tilde = nan;
    c.regime = Regime::singular;
    return c;
  }
  c.h = v.h;
  c.lambda = v.lambda;
  c.h_tilde = v.h_tilde;
  const double product = c.curvature * c.h_tilde;
  c.regime = product < 0 ? Regime::focusing : product > 0 ? Regime::defocusing : Regime::degenerate;
  return c;
}

NlsCoefficients coefficients(const Params& p, Branch b, double theta) {
  validate(p);
  if (!(std::isfinite(theta) && theta > -std::numbers::pi && theta <= std::numbers::pi))
    throw InvalidParameter("theta", "must be a wavenumber in (-pi, pi]");
  if (b == Branch::acoustic && theta == 0.0)
    throw InvalidParameter("theta", "must be nonzero on the acoustic branch (theta = 0 is the zero-frequency mode); "
                                    "valid range (-pi, 0) U (0, pi]");
  return coefficients_unchecked(p, taylor_coefficients(p), b, theta);
}

}  // namespace lrchain
