// GENERATED FILE - DO NOT EDIT.
// Written by lrchain-derive from models/resonant_chain_polynomial.toml (FNV-1a 64 0xd6c25d1014f797cc): the double evaluators of
// the model's dispersion relation and NLS coefficients (docs/models.md).
// Regenerate with `cmake --build build --target regenerate`.
#pragma once

#include <cmath>

#include "lrchain/model.hpp"
#include "lrchain/model_evaluator_support.hpp"

namespace lrchain::generated::model_resonant_chain_polynomial {

// q = the parameters p, then the named intermediates of the force laws.
inline void intermediates(const double* p, double* q) noexcept {
  q[0] = p[0];
  q[1] = p[1];
  q[2] = p[2];
  q[3] = p[3];
  q[4] = p[4];
  q[5] = p[5];
  q[6] = p[6];
}

// Coefficients of det M = 0 in ascending powers of omega^2 at D1 = 4 sin^2(theta/2), sigma = sin(theta).
inline void dispersion(double D1, double sigma, const double* q, double* w) noexcept {
  (void)sigma;
  (void)q;
  w[0] = D1 * q[0] * q[3];
  w[1] = (-(D1 * q[0] * q[6]) - (q[3]) - (q[3] * q[6]));
  w[2] = q[6];
}

// intermediates() in long double.
inline void intermediates_extended(const long double* p, long double* q) noexcept {
  using real [[maybe_unused]] = long double;
  q[0] = p[0];
  q[1] = p[1];
  q[2] = p[2];
  q[3] = p[3];
  q[4] = p[4];
  q[5] = p[5];
  q[6] = p[6];
}

// Coefficients of det M as dispersion(), in long double arithmetic.
inline void dispersion_extended(long double D1, long double sigma, const long double* Q, long double* w) noexcept {
  using real [[maybe_unused]] = long double;
  (void)sigma;
  (void)Q;
  w[0] = D1 * Q[0] * Q[3];
  w[1] = (-(D1 * Q[0] * Q[6]) - (Q[3]) - (Q[3] * Q[6]));
  w[2] = Q[6];
}

// NLS coefficients at omega on a branch of det M = 0 (outputs in lrchain::ModelOutput order). In long double: the terms of its factors cancel by up to 4.6e+05 (measured at derivation).
inline void nls(double D1_in, double sigma_in, double omega_in, const double* q, double* out) noexcept {
  using real [[maybe_unused]] = long double;
  using lrchain::model_evaluator::magnitude;
  long double parameters[7], intermediates[7];
  lrchain::model_evaluator::widen(q, parameters, 7);
  intermediates_extended(parameters, intermediates);
  real Q[7];
  lrchain::model_evaluator::widen(intermediates, Q, 7);
  // D1, sigma and omega consistent in `real` (sin^2 + cos^2 = 1 for theta/2, det M = 0).
  real D1, sigma;
  lrchain::model_evaluator::consistent_half_angle(D1_in, sigma_in, D1, sigma);
  real w[3];
  dispersion_extended(D1, sigma, Q, w);
  const real omega = lrchain::model_evaluator::polished_omega(w, 2, omega_in);
  real o[13];
  const real t0 = (Q[3] * Q[3]);
  const real t1 = (omega * omega);
  const real t2 = (Q[6] * Q[6]);
  const real t3 = (omega * omega * omega * omega);
  const real t4 = (-(t1 * Q[6]) + Q[3]);
  const real t5 = (t4 * t4);
  o[0] = t5 * Q[0] * sigma / ((t0 - (2.0 * t1 * Q[3] * Q[6]) + t0 * Q[6] + t2 * t3) * omega);
  o[1] = t5 / ((t0 - (2.0 * t1 * Q[3] * Q[6]) + t0 * Q[6] + t2 * t3) * omega);
  const real t6 = (Q[3] * Q[3] * Q[3]);
  const real t7 = (o[0] * o[0]);
  const real t8 = (Q[6] * Q[6] * Q[6]);
  const real t9 = (omega * omega * omega * omega * omega * omega);
  o[2] = (real(1.0) / 2.0) * (-(t6 * D1 * Q[0]) - (2.0 * t6 * t7) - (2.0 * t6 * t7 * Q[6]) - (2.0 * t8 * t9 * Q[0]) - (3.0 * t2 * t3 * D1 * Q[0] * Q[3]) - (6.0 * t0 * t2 * t7 * t1) - (6.0 * t0 * t1 * Q[0] * Q[6]) - (6.0 * t2 * t7 * t3 * Q[3]) + t8 * t9 * D1 * Q[0] + 2.0 * t6 * Q[0] + 2.0 * t8 * t7 * t9 + 3.0 * t0 * t1 * D1 * Q[0] * Q[6] + 6.0 * t0 * t7 * t1 * Q[6] + 6.0 * t2 * t3 * Q[0] * Q[3]) * o[1] / ((t4 * t4 * t4));
  o[3] = -(D1 * Q[1] * o[1]);
  const real t10 = (D1 * D1);
  const real t11 = -(t10 * Q[0] * Q[3]);
  const real t12 = -(16.0 * t1 * D1 * Q[0] * Q[6]);
  const real t13 = -(4.0 * t1 * Q[3]);
  const real t14 = -(4.0 * t1 * Q[3] * Q[6]);
  const real t15 = 16.0 * t3 * Q[6];
  const real t16 = 4.0 * t10 * t1 * Q[0] * Q[6];
  const real t17 = 4.0 * D1 * Q[0] * Q[3];
  o[4] = -((t11 + t12 + t13 + t14 + t15 + t16 + t17));
  const real t18 = -(Q[0]);
  const real t19 = t7 * Q[6];
  o[5] = (t7 + t18 + t19);
  const real t20 = (Q[6] * Q[6] * Q[6] * Q[6] * Q[6]);
  const real t21 = (omega * omega * omega * omega * omega * omega * omega * omega * omega * omega);
  const real t22 = (Q[3] * Q[3] * Q[3] * Q[3] * Q[3] * Q[3]);
  const real t23 = (Q[6] * Q[6] * Q[6] * Q[6]);
  const real t24 = (D1 * D1 * D1);
  const real t25 = (Q[1] * Q[1]);
  const real t26 = (omega * omega * omega * omega * omega * omega * omega * omega);
  const real t27 = (Q[4] * Q[4]);
  const real t28 = (D1 * D1 * D1 * D1);
  const real t29 = (Q[3] * Q[3] * Q[3] * Q[3] * Q[3]);
  const real t30 = (Q[3] * Q[3] * Q[3] * Q[3]);
  const real t31 = (omega * omega * omega * omega * omega * omega * omega * omega * omega * omega * omega * omega);
  o[6] = -((real(1.0) / 2.0) * (-(12.0 * t10 * t0 * t20 * t21 * Q[2]) - (12.0 * t10 * t22 * t1 * Q[2]) - (12.0 * t10 * t22 * t1 * Q[2] * Q[6]) - (12.0 * t0 * t23 * t21 * Q[5]) - (12.0 * t0 * t20 * t21 * Q[5]) - (136.0 * t24 * t25 * t0 * t23 * t26) - (16.0 * t10 * t27 * t20 * t21 * Q[0]) - (16.0 * t28 * t25 * t29 * t1 * Q[6]) - (176.0 * t24 * t25 * t30 * t2 * t3) - (204.0 * t10 * t0 * t23 * t21 * Q[2]) - (24.0 * t27 * t23 * t26 * D1 * Q[0] * Q[3]) - (264.0 * t10 * t30 * t2 * t9 * Q[2]) - (3.0 * t10 * t0 * t23 * t26 * Q[0] * Q[5]) - (3.0 * t28 * t22 * Q[0] * Q[2]) - (336.0 * t24 * t6 * t8 * t9 * Q[0] * Q[2]) - (48.0 * t24 * t20 * t21 * Q[0] * Q[2] * Q[3]) - (48.0 * t20 * t21 * D1 * Q[0] * Q[3] * Q[5]) - (51.0 * t28 * t0 * t23 * t26 * Q[0] * Q[2]) - (56.0 * t28 * t25 * t6 * t8 * t9) - (64.0 * t27 * t20 * t31) - (66.0 * t28 * t30 * t2 * t3 * Q[0] * Q[2]) - (72.0 * t10 * t30 * t8 * t9 * Q[2]) - (8.0 * t24 * t25 * t22) - (8.0 * t28 * t25 * t20 * t21 * Q[3]) - (96.0 * t24 * t29 * t1 * Q[0] * Q[2] * Q[6]) + 12.0 * t10 * t20 * t21 * Q[0] * Q[3] * Q[5] + 12.0 * t24 * t22 * Q[0] * Q[2] + 12.0 * t28 * t20 * t21 * Q[0] * Q[2] * Q[3] + 12.0 * t0 * t23 * t26 * D1 * Q[0] * Q[5] + 2.0 * t28 * t25 * t22 + 204.0 * t24 * t0 * t23 * t26 * Q[0] * Q[2] + 224.0 * t24 * t25 * t6 * t8 * t9 + 24.0 * t28 * t29 * t1 * Q[0] * Q[2] * Q[6] + 24.0 * t27 * t23 * t21 * Q[3] + 24.0 * t27 * t20 * t21 * Q[3] + 264.0 * t24 * t30 * t2 * t3 * Q[0] * Q[2] + 32.0 * t24 * t25 * t20 * t21 * Q[3] + 336.0 * t10 * t6 * t8 * t26 * Q[2] + 34.0 * t28 * t25 * t0 * t23 * t26 + 44.0 * t28 * t25 * t30 * t2 * t3 + 48.0 * t10 * t6 * t23 * t26 * Q[2] + 48.0 * t10 * t29 * t2 * t3 * Q[2] + 48.0 * t10 * t20 * t31 * Q[2] * Q[3] + 48.0 * t20 * t31 * Q[3] * Q[5] + 6.0 * t10 * t27 * t23 * t26 * Q[0] * Q[3] + 64.0 * t24 * t25 * t29 * t1 * Q[6] + 64.0 * t27 * t20 * t21 * D1 * Q[0] + 84.0 * t28 * t6 * t8 * t9 * Q[0] * Q[2] + 96.0 * t10 * t29 * t3 * Q[2] * Q[6]) * o[1] / ((t4 * t4 * t4 * t4) * Q[3] * o[4]));
  o[7] = 2.0 * D1 * Q[1] / (o[5]);
  o[8] = (-(o[3] * o[7]) + o[6]);
  o[9] = -((real(1.0) / 2.0) * (-(12.0 * t10 * t0 * t20 * t21 * Q[2] * o[1] * o[5]) - (12.0 * t10 * t22 * t1 * Q[2] * Q[6] * o[1] * o[5]) - (12.0 * t10 * t22 * t1 * Q[2] * o[1] * o[5]) - (12.0 * t0 * t23 * t21 * Q[5] * o[1] * o[5]) - (12.0 * t0 * t20 * t21 * Q[5] * o[1] * o[5]) - (136.0 * t24 * t25 * t0 * t23 * t26 * o[1] * o[5]) - (16.0 * t10 * t27 * t20 * t21 * Q[0] * o[1] * o[5]) - (16.0 * t28 * t25 * t29 * t1 * Q[6] * o[1] * o[5]) - (16.0 * t0 * t8 * t9 * D1 * Q[1] * o[3] * o[4]) - (16.0 * t30 * t1 * D1 * Q[1] * Q[6] * o[3] * o[4]) - (176.0 * t24 * t25 * t30 * t2 * t3 * o[1] * o[5]) - (204.0 * t10 * t0 * t23 * t21 * Q[2] * o[1] * o[5]) - (24.0 * t27 * t23 * t26 * D1 * Q[0] * Q[3] * o[1] * o[5]) - (264.0 * t10 * t30 * t2 * t9 * Q[2] * o[1] * o[5]) - (3.0 * t10 * t0 * t23 * t26 * Q[0] * Q[5] * o[1] * o[5]) - (3.0 * t28 * t22 * Q[0] * Q[2] * o[1] * o[5]) - (336.0 * t24 * t6 * t8 * t9 * Q[0] * Q[2] * o[1] * o[5]) - (48.0 * t24 * t20 * t21 * Q[0] * Q[2] * Q[3] * o[1] * o[5]) - (48.0 * t20 * t21 * D1 * Q[0] * Q[3] * Q[5] * o[1] * o[5]) - (51.0 * t28 * t0 * t23 * t26 * Q[0] * Q[2] * o[1] * o[5]) - (56.0 * t28 * t25 * t6 * t8 * t9 * o[1] * o[5]) - (64.0 * t27 * t20 * t31 * o[1] * o[5]) - (66.0 * t28 * t30 * t2 * t3 * Q[0] * Q[2] * o[1] * o[5]) - (72.0 * t10 * t30 * t8 * t9 * Q[2] * o[1] * o[5]) - (8.0 * t24 * t25 * t22 * o[1] * o[5]) - (8.0 * t28 * t25 * t20 * t21 * Q[3] * o[1] * o[5]) - (96.0 * t24 * t29 * t1 * Q[0] * Q[2] * Q[6] * o[1] * o[5]) + 12.0 * t10 * t20 * t21 * Q[0] * Q[3] * Q[5] * o[1] * o[5] + 12.0 * t24 * t22 * Q[0] * Q[2] * o[1] * o[5] + 12.0 * t28 * t20 * t21 * Q[0] * Q[2] * Q[3] * o[1] * o[5] + 12.0 * t0 * t23 * t26 * D1 * Q[0] * Q[5] * o[1] * o[5] + 2.0 * t28 * t25 * t22 * o[1] * o[5] + 204.0 * t24 * t0 * t23 * t26 * Q[0] * Q[2] * o[1] * o[5] + 224.0 * t24 * t25 * t6 * t8 * t9 * o[1] * o[5] + 24.0 * t28 * t29 * t1 * Q[0] * Q[2] * Q[6] * o[1] * o[5] + 24.0 * t6 * t2 * t3 * D1 * Q[1] * o[3] * o[4] + 24.0 * t27 * t23 * t21 * Q[3] * o[1] * o[5] + 24.0 * t27 * t20 * t21 * Q[3] * o[1] * o[5] + 264.0 * t24 * t30 * t2 * t3 * Q[0] * Q[2] * o[1] * o[5] + 32.0 * t24 * t25 * t20 * t21 * Q[3] * o[1] * o[5] + 336.0 * t10 * t6 * t8 * t26 * Q[2] * o[1] * o[5] + 34.0 * t28 * t25 * t0 * t23 * t26 * o[1] * o[5] + 4.0 * t29 * D1 * Q[1] * o[3] * o[4] + 4.0 * t23 * t26 * D1 * Q[1] * Q[3] * o[3] * o[4] + 44.0 * t28 * t25 * t30 * t2 * t3 * o[1] * o[5] + 48.0 * t10 * t6 * t23 * t26 * Q[2] * o[1] * o[5] + 48.0 * t10 * t29 * t2 * t3 * Q[2] * o[1] * o[5] + 48.0 * t10 * t20 * t31 * Q[2] * Q[3] * o[1] * o[5] + 48.0 * t20 * t31 * Q[3] * Q[5] * o[1] * o[5] + 6.0 * t10 * t27 * t23 * t26 * Q[0] * Q[3] * o[1] * o[5] + 64.0 * t24 * t25 * t29 * t1 * Q[6] * o[1] * o[5] + 64.0 * t27 * t20 * t21 * D1 * Q[0] * o[1] * o[5] + 84.0 * t28 * t6 * t8 * t9 * Q[0] * Q[2] * o[1] * o[5] + 96.0 * t10 * t29 * t3 * Q[2] * Q[6] * o[1] * o[5]) / ((t4 * t4 * t4 * t4) * Q[3]));
  o[10] = (-(t1 * D1 * Q[0] * Q[6]) - (t1 * Q[3]) - (t1 * Q[3] * Q[6]) + t3 * Q[6] + D1 * Q[0] * Q[3]);
  o[11] = (magnitude(t11) + magnitude(t12) + magnitude(t13) + magnitude(t14) + magnitude(t15) + magnitude(t16) + magnitude(t17));
  o[12] = (magnitude(t7) + magnitude(t18) + magnitude(t19));
  for (int k = 0; k < 13; ++k) out[k] = static_cast<double>(o[k]);
}

// Per field f, out[5f..5f+4]: second harmonic A_{2,2,f}/A_{1,1}^2 (real, imaginary part), mean A_{2,0,f}/|A_{1,1}|^2, gradient term of A_{2,1,f} per d_xi A_{1,1} (real, imaginary) (lrchain::HarmonicOutput).
inline void harmonics(double D1_in, double sigma_in, double omega_in, const double* q, double* out) noexcept {
  using real [[maybe_unused]] = long double;
  [[maybe_unused]] const auto magnitude = [](real x) { return x < 0 ? -x : x; };
  long double parameters[7], intermediates[7];
  lrchain::model_evaluator::widen(q, parameters, 7);
  intermediates_extended(parameters, intermediates);
  real Q[7];
  lrchain::model_evaluator::widen(intermediates, Q, 7);
  // D1, sigma and omega consistent in `real` (sin^2 + cos^2 = 1 for theta/2, det M = 0).
  real D1, sigma;
  lrchain::model_evaluator::consistent_half_angle(D1_in, sigma_in, D1, sigma);
  real w[3];
  dispersion_extended(D1, sigma, Q, w);
  const real omega = lrchain::model_evaluator::polished_omega(w, 2, omega_in);
  real o[10];
  const real t0 = (D1 * D1);
  const real t1 = (omega * omega);
  const real t2 = (omega * omega * omega * omega);
  o[0] = 4.0 * (Q[6] * Q[6] * Q[6]) * (omega * omega * omega * omega * omega * omega) * Q[4] / ((-(t0 * Q[0] * Q[3]) - (16.0 * t1 * D1 * Q[0] * Q[6]) - (4.0 * t1 * Q[3]) - (4.0 * t1 * Q[3] * Q[6]) + 16.0 * t2 * Q[6] + 4.0 * t0 * t1 * Q[0] * Q[6] + 4.0 * D1 * Q[0] * Q[3]) * (((-(t1 * Q[6]) + Q[3])) * ((-(t1 * Q[6]) + Q[3]))));
  o[1] = 2.0 * (-(Q[3]) + 4.0 * t1 * Q[6]) * D1 * Q[1] * sigma / ((-(t0 * Q[0] * Q[3]) - (16.0 * t1 * D1 * Q[0] * Q[6]) - (4.0 * t1 * Q[3]) - (4.0 * t1 * Q[3] * Q[6]) + 16.0 * t2 * Q[6] + 4.0 * t0 * t1 * Q[0] * Q[6] + 4.0 * D1 * Q[0] * Q[3]));
  o[2] = 0.0;
  o[3] = 0.0;
  o[4] = 0.0;
  const real t3 = (Q[6] * Q[6]);
  o[5] = (-(t0 * Q[0]) - (4.0 * t1) + 4.0 * D1 * Q[0]) * t3 * t2 * Q[4] / ((-(t0 * Q[0] * Q[3]) - (16.0 * t1 * D1 * Q[0] * Q[6]) - (4.0 * t1 * Q[3]) - (4.0 * t1 * Q[3] * Q[6]) + 16.0 * t2 * Q[6] + 4.0 * t0 * t1 * Q[0] * Q[6] + 4.0 * D1 * Q[0] * Q[3]) * (((-(t1 * Q[6]) + Q[3])) * ((-(t1 * Q[6]) + Q[3]))));
  o[6] = -(2.0 * D1 * Q[1] * Q[3] * sigma / ((-(t0 * Q[0] * Q[3]) - (16.0 * t1 * D1 * Q[0] * Q[6]) - (4.0 * t1 * Q[3]) - (4.0 * t1 * Q[3] * Q[6]) + 16.0 * t2 * Q[6] + 4.0 * t0 * t1 * Q[0] * Q[6] + 4.0 * D1 * Q[0] * Q[3])));
  o[7] = 2.0 * t3 * t2 * Q[4] / ((((-(t1 * Q[6]) + Q[3])) * ((-(t1 * Q[6]) + Q[3]))) * Q[3]);
  o[8] = 0.0;
  const real t4 = (Q[3] * Q[3]);
  o[9] = -(2.0 * Q[0] * Q[3] * Q[6] * sigma / ((t4 - (2.0 * t1 * Q[3] * Q[6]) + t4 * Q[6] + t3 * t2)));
  for (int k = 0; k < 10; ++k) out[k] = static_cast<double>(o[k]);
}

// The model's description for lrchain::Model (parameters, ranges, branches, evaluators).
inline lrchain::ModelDefinition definition() {
  lrchain::ModelDefinition d;
  d.name = "resonant_chain_polynomial";
  d.description = "locally resonant chain with polynomial bond forces and nonlinear resonators";
  d.file_hash = 0xd6c25d1014f797ccull;
  d.file_sha256 = "273d52b01dd940f5e01ff088c1c3b344a1700499d3e7a5380fd24d46b9b54478";
  d.parameters.push_back({"k1", "(0, inf)", 1, true, false, false, false, 0, 0});
  d.parameters.push_back({"b1", "(-inf, inf)", -0.25, false, false, false, false, 0, 0});
  d.parameters.push_back({"g1", "(-inf, inf)", 0.125, false, false, false, false, 0, 0});
  d.parameters.push_back({"k2", "(0, inf)", 1, true, false, false, false, 0, 0});
  d.parameters.push_back({"b2", "(-inf, inf)", 0, false, false, false, false, 0, 0});
  d.parameters.push_back({"g2", "(-inf, inf)", 0.10000000000000001, false, false, false, false, 0, 0});
  d.parameters.push_back({"rho", "(0, inf)", 0.33333333333333331, true, false, false, false, 0, 0});
  d.branch_names.push_back("acoustic");
  d.branch_names.push_back("optical");
  d.mean_flow = true;
  d.degree = 2;
  d.evaluators = {&intermediates, &dispersion, &nls, &harmonics, nullptr};
  return d;
}

}  // namespace lrchain::generated::model_resonant_chain_polynomial
