// GENERATED FILE - DO NOT EDIT.
// Written by lrchain-derive (derivation/, GiNaC 1.8) from the multiple-scale expansion of the lattice
// equations (eq:Hertz, eq:ansatz; Appendix A). Regenerate with `cmake --build build --target regenerate`.
// Inputs: D1 = 4 sin^2(theta/2), sigma = sin(theta), omega on the dispersion relation, and the
// model parameters (K2, K3, K4 from eq:expv). h and lambda divide by the non-resonance values
// (eq:nonresonance1, eq:nonresonance2); h_tilde_numerator = h_tilde * nonresonance1 * nonresonance2
// is smooth across those poles; dispersion = det L_1 (zero on the dispersion relation).
#pragma once

namespace lrchain::generated {

struct NlsValues {
  double group_velocity, gamma, curvature, beta, nonresonance1, nonresonance2, h, lambda, h_tilde,
      h_tilde_numerator, dispersion;
};

// NLS coefficients of the locally resonant granular chain (eq:Hertz), fields u (beads) and v (resonators).
inline NlsValues resonant_chain_nls(double D1, double sigma, double omega, double K2, double K3, double K4, double kappa, double rho) noexcept {
  NlsValues r{};
  const double t0 = (rho * rho);
  const double t1 = (omega * omega * omega * omega);
  const double t2 = (kappa * kappa);
  const double t3 = (omega * omega);
  const double t4 = (t0 * t1 + (rho + 1.0) * t2 - (2.0 * rho * t3 * kappa));
  const double t5 = (rho * t3 - (kappa));
  const double t6 = (t5 * t5);
  r.group_velocity = t6 * sigma * K2 / (omega * t4);
  r.gamma = t6 / (omega * t4);
  const double t7 = (kappa * kappa * kappa);
  const double t8 = (r.group_velocity * r.group_velocity);
  const double t9 = (rho * rho * rho);
  const double t10 = (omega * omega * omega * omega * omega * omega);
  r.curvature = (1.0 / 2.0) * r.gamma * (3.0 * t0 * D1 * t1 * kappa * K2 - (2.0 * t7 * K2) + 6.0 * t0 * t1 * t8 * kappa + D1 * t7 * K2 + 2.0 * t8 * t7 + 2.0 * t9 * t10 * K2 + 6.0 * t0 * t3 * t8 * t2 - (t9 * D1 * t10 * K2) - (2.0 * t9 * t10 * t8) + 2.0 * rho * t8 * t7 - (3.0 * rho * D1 * t3 * t2 * K2) - (6.0 * rho * t3 * t8 * t2) + 6.0 * rho * t3 * t2 * K2 - (6.0 * t0 * t1 * kappa * K2)) / ((t5 * t5 * t5));
  r.beta = -(r.gamma * K3 * D1);
  const double t11 = (D1 * D1);
  r.nonresonance1 = (16.0 * rho * D1 * t3 * K2 + t11 * kappa * K2 + 4.0 * t3 * kappa - (4.0 * D1 * kappa * K2) - (4.0 * rho * t11 * t3 * K2) - (16.0 * rho * t1) + 4.0 * rho * t3 * kappa);
  r.nonresonance2 = (rho * t8 + t8 - (K2));
  const double t12 = (K3 * K3);
  r.h = (1.0 / 2.0) * r.gamma * t11 * (12.0 * rho * t3 * K4 * kappa + 8.0 * t12 * D1 * kappa + 8.0 * rho * t12 * t11 * t3 - (3.0 * (4.0 * rho * t11 * t3 * K4 - (t11 * K4 * kappa) + 4.0 * D1 * K4 * kappa - (16.0 * rho * D1 * t3 * K4)) * K2) + 12.0 * t3 * K4 * kappa - (48.0 * rho * t1 * K4) - (2.0 * t12 * t11 * kappa) - (32.0 * rho * t12 * D1 * t3)) / (r.nonresonance1);
  r.lambda = 2.0 * K3 * D1 / (r.nonresonance2);
  r.h_tilde = (-(r.lambda * r.beta) + r.h);
  const double t13 = (D1 * D1 * D1);
  r.h_tilde_numerator = (1.0 / 2.0) * (2.0 * r.gamma * (6.0 * D1 * t3 * r.nonresonance2 * K4 * kappa + 4.0 * t12 * t11 * r.nonresonance2 * kappa - (t12 * t13 * r.nonresonance2 * kappa) + 2.0 * (2.0 * t12 * (t13 * t3 * r.nonresonance2 - (4.0 * t11 * t3 * r.nonresonance2)) - (3.0 * D1 * (4.0 * t1 * r.nonresonance2 * K4 - (t3 * r.nonresonance2 * K4 * kappa)))) * rho) - (3.0 * r.gamma * (4.0 * t11 * r.nonresonance2 * K4 * kappa + 4.0 * (t13 * t3 * r.nonresonance2 * K4 - (4.0 * t11 * t3 * r.nonresonance2 * K4)) * rho - (t13 * r.nonresonance2 * K4 * kappa)) * K2) - (4.0 * r.nonresonance1 * K3 * r.beta)) * D1;
  r.dispersion = (-(rho * D1 * t3 * K2) - (t3 * kappa) + D1 * kappa * K2 + rho * t1 - (rho * t3 * kappa));
  return r;
}

// NLS coefficients of the homogeneous precompressed granular chain (rho -> 0 limit, Chong13), field u.
inline NlsValues homogeneous_chain_nls(double D1, double sigma, double omega, double K2, double K3, double K4) noexcept {
  NlsValues r{};
  r.group_velocity = sigma * K2 / (omega);
  const double t0 = (1.0 / omega);
  r.gamma = t0;
  const double t1 = D1 * K2;
  const double t2 = (r.group_velocity * r.group_velocity);
  r.curvature = -((1.0 / 2.0) * r.gamma * (t1 + 2.0 * t2 - (2.0 * K2)));
  r.beta = -(r.gamma * K3 * D1);
  const double t3 = (D1 * D1);
  const double t4 = (omega * omega);
  r.nonresonance1 = (-(4.0 * D1 * K2) + t3 * K2 + 4.0 * t4);
  r.nonresonance2 = (t2 - (K2));
  const double t5 = (K3 * K3);
  r.h = (1.0 / 2.0) * r.gamma * (12.0 * t4 * K4 + 3.0 * (t3 * K4 - (4.0 * D1 * K4)) * K2 - (2.0 * t5 * t3) + 8.0 * t5 * D1) * t3 / (r.nonresonance1);
  r.lambda = 2.0 * K3 * D1 / (r.nonresonance2);
  r.h_tilde = (r.h - (r.beta * r.lambda));
  const double t6 = (D1 * D1 * D1);
  r.h_tilde_numerator = (1.0 / 2.0) * (2.0 * r.nonresonance2 * r.gamma * ((4.0 * t3 - (t6)) * t5 + 6.0 * D1 * t4 * K4) - (4.0 * K3 * r.beta * r.nonresonance1) + 3.0 * r.nonresonance2 * r.gamma * (t6 * K4 - (4.0 * t3 * K4)) * K2) * D1;
  r.dispersion = (t1 - (t4));
  return r;
}

}  // namespace lrchain::generated
