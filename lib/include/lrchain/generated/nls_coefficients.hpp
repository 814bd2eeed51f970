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
  const double t0 = (kappa * kappa);
  const double t1 = t0 * rho;
  const double t2 = (mu * mu);
  const double t3 = (t1 + t2);
  r.group_velocity = K2 * t2 * sigma / (t3 * omega);
  r.gamma = t2 / (t3 * omega);
  const double t4 = (mu * mu * mu);
  const double t5 = (r.group_velocity * r.group_velocity);
  r.curvature = -((1.0 / 2.0) * (-(2.0 * K2 * t4) - (6.0 * t5 * t0 * mu * rho) - (8.0 * t5 * (kappa * kappa * kappa) * rho) + 2.0 * t5 * t4 + D1 * K2 * t4) * r.gamma / ((mu * mu * mu)));
  r.beta = -(D1 * K3 * r.gamma);
  const double t6 = (omega * omega * omega * omega);
  const double t7 = (D1 * D1);
  const double t8 = (omega * omega);
  r.nonresonance1 = (-(16.0 * t6 * rho) - (4.0 * D1 * K2 * kappa) - (4.0 * t7 * K2 * t8 * rho) + 16.0 * D1 * K2 * t8 * rho + 4.0 * kappa * t8 + 4.0 * kappa * t8 * rho + t7 * K2 * kappa);
  r.nonresonance2 = (-(K2) + t5 * rho + t5);
  const double t9 = (K3 * K3);
  r.h = (1.0 / 2.0) * (-(12.0 * D1 * K2 * K4 * kappa) - (12.0 * t7 * K2 * K4 * t8 * rho) - (2.0 * t7 * t9 * kappa) - (32.0 * D1 * t9 * t8 * rho) - (48.0 * K4 * t6 * rho) + 12.0 * K4 * kappa * t8 + 12.0 * K4 * kappa * t8 * rho + 3.0 * t7 * K2 * K4 * kappa + 48.0 * D1 * K2 * K4 * t8 * rho + 8.0 * D1 * t9 * kappa + 8.0 * t7 * t9 * t8 * rho) * t7 * r.gamma / (r.nonresonance1);
  r.lambda = 2.0 * D1 * K3 / (r.nonresonance2);
  r.h_tilde = (-(r.beta * r.lambda) + r.h);
  const double t10 = (D1 * D1 * D1);
  r.h_tilde_numerator = (1.0 / 2.0) * (-(12.0 * t7 * K2 * K4 * r.gamma * kappa * r.nonresonance2) - (12.0 * t10 * K2 * K4 * r.gamma * r.nonresonance2 * t8 * rho) - (2.0 * t10 * t9 * r.gamma * kappa * r.nonresonance2) - (32.0 * t7 * t9 * r.gamma * r.nonresonance2 * t8 * rho) - (4.0 * K3 * r.beta * r.nonresonance1) - (48.0 * D1 * K4 * r.gamma * r.nonresonance2 * t6 * rho) + 12.0 * D1 * K4 * r.gamma * kappa * r.nonresonance2 * t8 + 12.0 * D1 * K4 * r.gamma * kappa * r.nonresonance2 * t8 * rho + 3.0 * t10 * K2 * K4 * r.gamma * kappa * r.nonresonance2 + 48.0 * t7 * K2 * K4 * r.gamma * r.nonresonance2 * t8 * rho + 8.0 * t7 * t9 * r.gamma * kappa * r.nonresonance2 + 8.0 * t10 * t9 * r.gamma * r.nonresonance2 * t8 * rho) * D1;
  r.dispersion = -((-(kappa * mu) - (t2) + D1 * K2 * mu * rho + kappa * mu * rho + t1) / (rho));
  return r;
}

// NLS coefficients of the homogeneous precompressed granular chain (rho -> 0 limit, Chong13), field u.
inline NlsValues homogeneous_chain_nls(double D1, double sigma, double omega, double K2, double K3, double K4) noexcept {
  NlsValues r{};
  r.group_velocity = K2 * sigma / (omega);
  const double t0 = (1.0 / omega);
  r.gamma = t0;
  const double t1 = (r.group_velocity * r.group_velocity);
  const double t2 = D1 * K2;
  r.curvature = -((1.0 / 2.0) * (-(2.0 * K2) + 2.0 * t1 + t2) * r.gamma);
  r.beta = -(D1 * K3 * r.gamma);
  const double t3 = (omega * omega);
  const double t4 = (D1 * D1);
  r.nonresonance1 = (-(4.0 * D1 * K2) + 4.0 * t3 + t4 * K2);
  r.nonresonance2 = (-(K2) + t1);
  const double t5 = (K3 * K3);
  r.h = (1.0 / 2.0) * (-(12.0 * D1 * K2 * K4) - (2.0 * t4 * t5) + 12.0 * K4 * t3 + 3.0 * t4 * K2 * K4 + 8.0 * D1 * t5) * t4 * r.gamma / (r.nonresonance1);
  r.lambda = 2.0 * D1 * K3 / (r.nonresonance2);
  r.h_tilde = (-(r.beta * r.lambda) + r.h);
  const double t6 = (D1 * D1 * D1);
  r.h_tilde_numerator = (1.0 / 2.0) * (-(12.0 * t4 * K2 * K4 * r.gamma * r.nonresonance2) - (2.0 * t6 * t5 * r.gamma * r.nonresonance2) - (4.0 * K3 * r.beta * r.nonresonance1) + 12.0 * D1 * K4 * r.gamma * r.nonresonance2 * t3 + 3.0 * t6 * K2 * K4 * r.gamma * r.nonresonance2 + 8.0 * t4 * t5 * r.gamma * r.nonresonance2) * D1;
  r.dispersion = (-(t3) + t2);
  return r;
}

}  // namespace lrchain::generated
