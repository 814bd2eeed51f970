#pragma once
// The resonant chain's NLS coefficients at one wavenumber from sin(theta/2) and cos(theta/2):
// straight-line code with selects instead of branches, so that a loop over many wavenumbers
// vectorises. coefficients_unchecked() and the batch loop (coefficients_batch.hpp) both call it,
// which keeps them bit-identical (IEEE +, -, *, /, sqrt and selects only; no contraction).
#include <cmath>
#include <limits>

#include "lrchain/coefficients.hpp"
#include "lrchain/generated/nls_coefficients.hpp"

namespace lrchain::detail {

// Coefficients of (eq:mod1)-(eq:NLS) from the generated evaluators; omega from (eq:disp1d).
// sh = sin(theta/2), ch = cos(theta/2).
template <Branch branch>
inline NlsCoefficients coefficients_from_half_angle(const Params& p, const TaylorCoefficients& K, double theta,
                                                    double sh, double ch) noexcept {
  const double D1 = 4.0 * sh * sh;  // 4 sin^2(theta/2), no cancellation near theta = 0
  const double sigma = 2.0 * sh * ch;
  // (eq:disp1d) in the cancellation-free form of dispersion_omega().
  const double D = K.K2 * D1, kr = p.kappa / p.rho;
  const double m = D + p.kappa - kr;
  const double upper = 0.5 * (D + p.kappa + kr + std::sqrt(m * m + 4.0 * p.kappa * kr));
  const double omega = branch == Branch::optical ? std::sqrt(upper) : std::sqrt(D * kr / upper);
  // mu = rho omega^2 - kappa, the root of mu^2 - B mu - rho kappa^2 = 0 (det M = 0 rewritten),
  // B = rho (D + kappa) - kappa; positive root on the optical branch, negative on the acoustic one,
  // both forms computed and the one without cancellation selected.
  const double B = p.rho * (D + p.kappa) - p.kappa;
  const double disc = std::sqrt(B * B + 4.0 * p.rho * p.kappa * p.kappa);
  const double rk2 = 2.0 * p.rho * p.kappa * p.kappa;
  const double mu_sum = branch == Branch::optical ? 0.5 * (B + disc) : 0.5 * (B - disc);
  const double mu_quotient = branch == Branch::optical ? rk2 / (disc - B) : -rk2 / (B + disc);
  const double mu = (branch == Branch::optical ? B >= 0.0 : B <= 0.0) ? mu_sum : mu_quotient;

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
  const bool singular = std::abs(v.nonresonance1) <= kNonresonanceTolerance * scale1 ||
                        std::abs(v.nonresonance2) <= kNonresonanceTolerance * scale2;
  const double nan = std::numeric_limits<double>::quiet_NaN();
  c.h = singular ? nan : v.h;
  c.lambda = singular ? nan : v.lambda;
  c.h_tilde = singular ? nan : v.h_tilde;
  const double product = c.curvature * v.h_tilde;
  const Regime regime = product < 0 ? Regime::focusing : product > 0 ? Regime::defocusing : Regime::degenerate;
  c.regime = singular ? Regime::singular : regime;
  return c;
}

}  // namespace lrchain::detail
