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
inline NlsValues resonant_chain_nls(double D1, double sigma, double omega, double K2, double K3, double K4, double kappa, double rho, double mu) noexcept {
  NlsValues r{};
  const double t0 = (mu * mu);
  const double t1 = (kappa * kappa);
  r.group_velocity = t0 * K2 * sigma / ((t0 + t1 * rho) * omega);
  r.gamma = t0 / ((t0 + t1 * rho) * omega);
  const double t2 = (mu * mu * mu);
  const double t3 = (r.group_velocity * r.group_velocity);
  r.curvature = (1.0 / 2.0) * (-(t2 * D1 * K2) - (2.0 * t2 * t3) + 2.0 * t2 * K2 + 6.0 * t1 * t3 * mu * rho + 8.0 * (kappa * kappa * kappa) * t3 * rho) * r.gamma / ((mu * mu * mu));
  r.beta = -(D1 * K3 * r.gamma);
  const double t4 = (D1 * D1);
  const double t5 = (omega * omega);
  const double t6 = (omega * omega * omega * omega);
  r.nonresonance1 = -((-(t4 * K2 * kappa) - (16.0 * t5 * D1 * K2 * rho) - (4.0 * t5 * kappa) - (4.0 * t5 * kappa * rho) + 16.0 * t6 * rho + 4.0 * t4 * t5 * K2 * rho + 4.0 * D1 * K2 * kappa));
  r.nonresonance2 = (t3 - (K2) + t3 * rho);
  const double t7 = (K3 * K3);
  r.h = (1.0 / 2.0) * (-(12.0 * t4 * t5 * K2 * K4 * rho) - (12.0 * D1 * K2 * K4 * kappa) - (2.0 * t4 * t7 * kappa) - (32.0 * t7 * t5 * D1 * rho) - (48.0 * t6 * K4 * rho) + 12.0 * t5 * K4 * kappa + 12.0 * t5 * K4 * kappa * rho + 3.0 * t4 * K2 * K4 * kappa + 48.0 * t5 * D1 * K2 * K4 * rho + 8.0 * t4 * t7 * t5 * rho + 8.0 * t7 * D1 * kappa) * t4 * r.gamma / (r.nonresonance1);
  r.lambda = 2.0 * D1 * K3 / (r.nonresonance2);
  r.h_tilde = (-(r.beta * r.lambda) + r.h);
  const double t8 = (D1 * D1 * D1);
  r.h_tilde_numerator = (1.0 / 2.0) * (-(12.0 * t4 * K2 * K4 * kappa * r.gamma * r.nonresonance2) - (12.0 * t8 * t5 * K2 * K4 * r.gamma * r.nonresonance2 * rho) - (2.0 * t8 * t7 * kappa * r.gamma * r.nonresonance2) - (32.0 * t4 * t7 * t5 * r.gamma * r.nonresonance2 * rho) - (4.0 * K3 * r.beta * r.nonresonance1) - (48.0 * t6 * D1 * K4 * r.gamma * r.nonresonance2 * rho) + 12.0 * t5 * D1 * K4 * kappa * r.gamma * r.nonresonance2 + 12.0 * t5 * D1 * K4 * kappa * r.gamma * r.nonresonance2 * rho + 3.0 * t8 * K2 * K4 * kappa * r.gamma * r.nonresonance2 + 48.0 * t4 * t5 * K2 * K4 * r.gamma * r.nonresonance2 * rho + 8.0 * t4 * t7 * kappa * r.gamma * r.nonresonance2 + 8.0 * t8 * t7 * t5 * r.gamma * r.nonresonance2 * rho) * D1;
  r.dispersion = (t0 - (t1 * rho) - (D1 * K2 * mu * rho) - (kappa * mu * rho) + kappa * mu) / (rho);
  return r;
}

// NLS coefficients of the homogeneous precompressed granular chain (rho -> 0 limit, Chong13), field u.
inline NlsValues homogeneous_chain_nls(double D1, double sigma, double omega, double K2, double K3, double K4) noexcept {
  NlsValues r{};
  r.group_velocity = K2 * sigma / (omega);
  const double t0 = (1.0 / omega);
  r.gamma = t0;
  const double t1 = -(D1 * K2);
  const double t2 = (r.group_velocity * r.group_velocity);
  r.curvature = (1.0 / 2.0) * (t1 - (2.0 * t2) + 2.0 * K2) * r.gamma;
  r.beta = -(D1 * K3 * r.gamma);
  const double t3 = (D1 * D1);
  const double t4 = (omega * omega);
  r.nonresonance1 = -((-(t3 * K2) - (4.0 * t4) + 4.0 * D1 * K2));
  r.nonresonance2 = (t2 - (K2));
  const double t5 = (K3 * K3);
  r.h = -((1.0 / 2.0) * (-(12.0 * t4 * K4) - (3.0 * t3 * K2 * K4) - (8.0 * t5 * D1) + 12.0 * D1 * K2 * K4 + 2.0 * t3 * t5) * t3 * r.gamma / (r.nonresonance1));
  r.lambda = 2.0 * D1 * K3 / (r.nonresonance2);
  r.h_tilde = (-(r.beta * r.lambda) + r.h);
  const double t6 = (D1 * D1 * D1);
  r.h_tilde_numerator = (1.0 / 2.0) * (-(12.0 * t3 * K2 * K4 * r.gamma * r.nonresonance2) - (2.0 * t6 * t5 * r.gamma * r.nonresonance2) - (4.0 * K3 * r.beta * r.nonresonance1) + 12.0 * t4 * D1 * K4 * r.gamma * r.nonresonance2 + 3.0 * t6 * K2 * K4 * r.gamma * r.nonresonance2 + 8.0 * t3 * t5 * r.gamma * r.nonresonance2) * D1;
  r.dispersion = -((t4 + t1));
  return r;
}

}  // namespace lrchain::generated
