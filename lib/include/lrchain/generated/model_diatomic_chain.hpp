// GENERATED FILE - DO NOT EDIT.
// Written by lrchain-derive from models/diatomic_chain.toml (FNV-1a 64 0xe672bce94294c28b): the double evaluators of
// the model's dispersion relation and NLS coefficients (docs/models.md).
// Regenerate with `cmake --build build --target regenerate`.
#pragma once

#include <cmath>

#include "lrchain/model.hpp"
#include "lrchain/model_evaluator_support.hpp"

namespace lrchain::generated::model_diatomic_chain {

// q = the parameters p, then the named intermediates of the force laws.
inline void intermediates(const double* p, double* q) noexcept {
  q[0] = p[0];
  q[1] = p[1];
  q[2] = p[2];
  const double t0 = std::pow(p[1], p[0]);
  q[3] = p[0] * t0 / (p[1]);
  const double t1 = -(p[0]);
  const double t2 = (t1 + 1.0);
  q[4] = (1.0 / 2.0) * t2 * p[0] * t0 / ((p[1] * p[1]));
  q[5] = (1.0 / 6.0) * t2 * (t1 + 2.0) * p[0] * t0 / ((p[1] * p[1] * p[1]));
}

// Coefficients of det M = 0 in ascending powers of omega^2 at D1 = 4 sin^2(theta/2), sigma = sin(theta).
inline void dispersion(double D1, double sigma, const double* q, double* w) noexcept {
  (void)sigma;
  (void)q;
  w[0] = -(((D1 * D1) - (8.0 * D1) + 4.0 * (sigma * sigma)) * (q[3] * q[3]));
  w[1] = 8.0 * ((-1.0) - (q[2])) * q[3];
  w[2] = 4.0 * q[2];
}

// intermediates() in long double.
inline void intermediates_extended(const long double* p, long double* q) noexcept {
  using real [[maybe_unused]] = long double;
  q[0] = p[0];
  q[1] = p[1];
  q[2] = p[2];
  const real t0 = std::pow(p[1], p[0]);
  q[3] = p[0] * t0 / (p[1]);
  const real t1 = -(p[0]);
  const real t2 = (t1 + 1.0);
  q[4] = (real(1.0) / 2.0) * t2 * p[0] * t0 / ((p[1] * p[1]));
  q[5] = (real(1.0) / 6.0) * t2 * (t1 + 2.0) * p[0] * t0 / ((p[1] * p[1] * p[1]));
}

// Coefficients of det M as dispersion(), in __float128 arithmetic.
inline void dispersion_extended(__float128 D1, __float128 sigma, const __float128* Q, __float128* w) noexcept {
  using real [[maybe_unused]] = __float128;
  (void)sigma;
  (void)Q;
  w[0] = -(((D1 * D1) - (8.0 * D1) + 4.0 * (sigma * sigma)) * (Q[3] * Q[3]));
  w[1] = 8.0 * ((-1.0) - (Q[2])) * Q[3];
  w[2] = 4.0 * Q[2];
}

// NLS coefficients at omega on a branch of det M = 0 (outputs in lrchain::ModelOutput order). In __float128: the terms of its factors cancel by up to 1e+13 (measured at derivation).
inline void nls(double D1_in, double sigma_in, double omega_in, const double* q, double* out) noexcept {
  using real [[maybe_unused]] = __float128;
  using lrchain::model_evaluator::magnitude;
  long double parameters[3], intermediates[6];
  lrchain::model_evaluator::widen(q, parameters, 3);
  intermediates_extended(parameters, intermediates);
  real Q[6];
  lrchain::model_evaluator::widen(intermediates, Q, 6);
  // D1, sigma and omega consistent in `real` (sin^2 + cos^2 = 1 for theta/2, det M = 0).
  real D1, sigma;
  lrchain::model_evaluator::consistent_half_angle(D1_in, sigma_in, D1, sigma);
  real w[3];
  dispersion_extended(D1, sigma, Q, w);
  const real omega = lrchain::model_evaluator::polished_omega(w, 2, omega_in);
  real o[13];
  const real t0 = (D1 * D1);
  const real t1 = (Q[3] * Q[3]);
  const real t2 = -(t0 * t1);
  const real t3 = (sigma * sigma);
  const real t4 = -(4.0 * t1 * t3);
  const real t5 = (omega * omega * omega * omega);
  const real t6 = (omega * omega);
  const real t7 = 8.0 * t1 * D1;
  o[0] = 4.0 * (t6 - (2.0 * Q[3])) * t1 * sigma / ((t2 - (16.0 * t1) - (16.0 * t1 * Q[2]) + t4 - (4.0 * t5 * Q[2]) + 16.0 * t6 * Q[2] * Q[3] + t7) * omega);
  const real t8 = (-(D1) + 4.0);
  o[1] = t8 * t1 / ((-(t1 * D1) - (4.0 * t6 * Q[2] * Q[3]) + t5 * Q[2] + 4.0 * t1 + 4.0 * t1 * Q[2]) * omega);
  const real t9 = (Q[3] * Q[3] * Q[3]);
  const real t10 = (o[0] * o[0]);
  const real t11 = (Q[3] * Q[3] * Q[3] * Q[3]);
  const real t12 = (Q[2] * Q[2]);
  const real t13 = (omega * omega * omega * omega * omega * omega);
  o[2] = (real(1.0) / 2.0) * (-(t1 * t5 * D1 * Q[2]) - (16.0 * t9 * t10) - (16.0 * t9 * t10 * Q[2]) - (2.0 * t1 * t10 * t6 * D1 * Q[2]) - (2.0 * t11 * D1) - (24.0 * t12 * t1 * t10 * t6) - (4.0 * t10 * t5 * Q[2] * Q[3]) - (6.0 * t12 * t10 * t13) - (8.0 * t1 * (omega * omega * omega) * Q[2] * o[0] * sigma) - (8.0 * t9 * t6) - (8.0 * t9 * t6 * Q[2]) + 16.0 * t9 * Q[2] * o[0] * omega * sigma + 2.0 * t9 * t6 * D1 + 2.0 * t9 * t6 * D1 * Q[2] + 24.0 * t12 * t10 * t5 * Q[3] + 24.0 * t1 * t10 * t6 * Q[2] + 4.0 * t1 * t5 * Q[2] + 4.0 * t9 * t10 * D1 + 8.0 * t11) * o[1] / ((-(t6 * Q[2]) + 2.0 * Q[3]) * t8 * (Q[3] * Q[3]));
  const real t14 = (t5 - (t6 * D1 * Q[3]) + t1 * D1);
  o[3] = -(t14 * Q[4] * o[1] / (t8 * (Q[3] * Q[3])));
  const real t15 = (D1 * D1 * D1 * D1);
  const real t16 = -(t15 * t1);
  const real t17 = -(16.0 * t1 * t3);
  const real t18 = -(24.0 * t0 * t1);
  const real t19 = -(32.0 * t6 * Q[2] * Q[3]);
  const real t20 = -(32.0 * t6 * Q[3]);
  const real t21 = -(4.0 * t0 * t1 * t3);
  const real t22 = 16.0 * t1 * t3 * D1;
  const real t23 = 32.0 * t1 * D1;
  const real t24 = 64.0 * t5 * Q[2];
  const real t25 = (D1 * D1 * D1);
  const real t26 = 8.0 * t25 * t1;
  o[4] = -((real(1.0) / 4.0) * (t16 + t17 + t18 + t19 + t20 + t21 + t22 + t23 + t24 + t26));
  const real t27 = -(Q[3]);
  const real t28 = 2.0 * t10;
  const real t29 = 2.0 * t10 * Q[2];
  o[5] = (real(1.0) / 2.0) * (t27 + t28 + t29);
  const real t30 = (Q[4] * Q[4]);
  const real t31 = (Q[3] * Q[3] * Q[3] * Q[3] * Q[3] * Q[3]);
  const real t32 = (omega * omega * omega * omega * omega * omega * omega * omega);
  const real t33 = (omega * omega * omega * omega * omega * omega * omega * omega * omega * omega);
  const real t34 = (Q[3] * Q[3] * Q[3] * Q[3] * Q[3]);
  const real t35 = (omega * omega * omega * omega * omega * omega * omega * omega * omega * omega * omega * omega);
  o[6] = (-(12.0 * t25 * t9 * t30 * t5) - (12.0 * t25 * t31 * Q[5]) - (144.0 * t1 * t32 * D1 * Q[2] * Q[5]) - (16.0 * t0 * t30 * t32 * Q[2] * Q[3]) - (16.0 * t30 * t33 * D1 * Q[2]) - (2.0 * t0 * t30 * t32 * Q[3]) - (2.0 * t15 * t9 * t30 * t5) - (2.0 * t15 * t34 * t30) - (32.0 * t25 * t11 * t30 * t6) - (48.0 * t0 * t1 * t32 * Q[2] * Q[5]) - (48.0 * t35 * Q[2] * Q[5]) - (6.0 * t25 * t9 * t13 * Q[5]) - (6.0 * t25 * t11 * t5 * Q[5]) - (6.0 * t15 * t34 * t6 * Q[5]) - (60.0 * t1 * t32 * D1 * Q[5]) - (64.0 * t1 * t30 * t13 * D1) - (64.0 * t1 * t30 * t13 * D1 * Q[2]) - (72.0 * t0 * t11 * t5 * Q[5]) - (96.0 * t0 * t11 * t5 * Q[2] * Q[5]) + 120.0 * t0 * t9 * t13 * Q[2] * Q[5] + 16.0 * t0 * t1 * t30 * t13 * Q[2] + 24.0 * t0 * t34 * t6 * Q[2] * Q[5] + 24.0 * t0 * t34 * t6 * Q[5] + 24.0 * t25 * t34 * t6 * Q[5] + 24.0 * t33 * Q[2] * Q[3] * Q[5] + 24.0 * t33 * Q[3] * Q[5] + 3.0 * t0 * t1 * t32 * Q[5] + 3.0 * t15 * t11 * t5 * Q[5] + 3.0 * t15 * t31 * Q[5] + 4.0 * t0 * t30 * t33 * Q[2] + 4.0 * t25 * t1 * t30 * t13 + 48.0 * t0 * t9 * t13 * Q[5] + 48.0 * t9 * t13 * D1 * Q[2] * Q[5] + 48.0 * t9 * t13 * D1 * Q[5] + 64.0 * t30 * t32 * D1 * Q[2] * Q[3] + 8.0 * t25 * t34 * t30 + 8.0 * t15 * t11 * t30 * t6 + 8.0 * t30 * t32 * D1 * Q[3] + 80.0 * t0 * t9 * t30 * t5 + 96.0 * t33 * D1 * Q[2] * Q[3] * Q[5]) * o[1] / ((t8 * t8) * (Q[3] * Q[3] * Q[3] * Q[3]) * o[4]);
  o[7] = 2.0 * t14 * Q[4] / (t8 * (Q[3] * Q[3]) * o[5]);
  o[8] = (-(o[3] * o[7]) + o[6]);
  o[9] = (-(12.0 * t25 * t9 * t30 * t5 * o[1] * o[5]) - (12.0 * t25 * t31 * Q[5] * o[1] * o[5]) - (144.0 * t1 * t32 * D1 * Q[2] * Q[5] * o[1] * o[5]) - (16.0 * t0 * t30 * t32 * Q[2] * Q[3] * o[1] * o[5]) - (16.0 * t30 * t33 * D1 * Q[2] * o[1] * o[5]) - (2.0 * t0 * t9 * t6 * Q[4] * o[3] * o[4]) - (2.0 * t0 * t30 * t32 * Q[3] * o[1] * o[5]) - (2.0 * t15 * t9 * t30 * t5 * o[1] * o[5]) - (2.0 * t15 * t34 * t30 * o[1] * o[5]) - (32.0 * t25 * t11 * t30 * t6 * o[1] * o[5]) - (48.0 * t0 * t1 * t32 * Q[2] * Q[5] * o[1] * o[5]) - (48.0 * t35 * Q[2] * Q[5] * o[1] * o[5]) - (6.0 * t25 * t9 * t13 * Q[5] * o[1] * o[5]) - (6.0 * t25 * t11 * t5 * Q[5] * o[1] * o[5]) - (6.0 * t15 * t34 * t6 * Q[5] * o[1] * o[5]) - (60.0 * t1 * t32 * D1 * Q[5] * o[1] * o[5]) - (64.0 * t1 * t30 * t13 * D1 * Q[2] * o[1] * o[5]) - (64.0 * t1 * t30 * t13 * D1 * o[1] * o[5]) - (72.0 * t0 * t11 * t5 * Q[5] * o[1] * o[5]) - (8.0 * t1 * t5 * Q[4] * o[3] * o[4]) - (8.0 * t11 * D1 * Q[4] * o[3] * o[4]) - (96.0 * t0 * t11 * t5 * Q[2] * Q[5] * o[1] * o[5]) + 120.0 * t0 * t9 * t13 * Q[2] * Q[5] * o[1] * o[5] + 16.0 * t0 * t1 * t30 * t13 * Q[2] * o[1] * o[5] + 2.0 * t0 * t11 * Q[4] * o[3] * o[4] + 2.0 * t1 * t5 * D1 * Q[4] * o[3] * o[4] + 24.0 * t0 * t34 * t6 * Q[2] * Q[5] * o[1] * o[5] + 24.0 * t0 * t34 * t6 * Q[5] * o[1] * o[5] + 24.0 * t25 * t34 * t6 * Q[5] * o[1] * o[5] + 24.0 * t33 * Q[2] * Q[3] * Q[5] * o[1] * o[5] + 24.0 * t33 * Q[3] * Q[5] * o[1] * o[5] + 3.0 * t0 * t1 * t32 * Q[5] * o[1] * o[5] + 3.0 * t15 * t11 * t5 * Q[5] * o[1] * o[5] + 3.0 * t15 * t31 * Q[5] * o[1] * o[5] + 4.0 * t0 * t30 * t33 * Q[2] * o[1] * o[5] + 4.0 * t25 * t1 * t30 * t13 * o[1] * o[5] + 48.0 * t0 * t9 * t13 * Q[5] * o[1] * o[5] + 48.0 * t9 * t13 * D1 * Q[2] * Q[5] * o[1] * o[5] + 48.0 * t9 * t13 * D1 * Q[5] * o[1] * o[5] + 64.0 * t30 * t32 * D1 * Q[2] * Q[3] * o[1] * o[5] + 8.0 * t25 * t34 * t30 * o[1] * o[5] + 8.0 * t15 * t11 * t30 * t6 * o[1] * o[5] + 8.0 * t9 * t6 * D1 * Q[4] * o[3] * o[4] + 8.0 * t30 * t32 * D1 * Q[3] * o[1] * o[5] + 80.0 * t0 * t9 * t30 * t5 * o[1] * o[5] + 96.0 * t33 * D1 * Q[2] * Q[3] * Q[5] * o[1] * o[5]) / ((t8 * t8) * (Q[3] * Q[3] * Q[3] * Q[3]));
  o[10] = (real(1.0) / 4.0) * (t2 + t4 - (8.0 * t6 * Q[2] * Q[3]) - (8.0 * t6 * Q[3]) + 4.0 * t5 * Q[2] + t7);
  o[11] = (magnitude(t16) + magnitude(t17) + magnitude(t18) + magnitude(t19) + magnitude(t20) + magnitude(t21) + magnitude(t22) + magnitude(t23) + magnitude(t24) + magnitude(t26)) / (magnitude(4.0));
  o[12] = (magnitude(t27) + magnitude(t28) + magnitude(t29)) / (magnitude(2.0));
  for (int k = 0; k < 13; ++k) out[k] = static_cast<double>(o[k]);
}

// Per field f, out[5f..5f+4]: second harmonic A_{2,2,f}/A_{1,1}^2 (real, imaginary part), mean A_{2,0,f}/|A_{1,1}|^2, gradient term of A_{2,1,f} per d_xi A_{1,1} (real, imaginary) (lrchain::HarmonicOutput).
inline void harmonics(double D1_in, double sigma_in, double omega_in, const double* q, double* out) noexcept {
  using real [[maybe_unused]] = __float128;
  [[maybe_unused]] const auto magnitude = [](real x) { return x < 0 ? -x : x; };
  long double parameters[3], intermediates[6];
  lrchain::model_evaluator::widen(q, parameters, 3);
  intermediates_extended(parameters, intermediates);
  real Q[6];
  lrchain::model_evaluator::widen(intermediates, Q, 6);
  // D1, sigma and omega consistent in `real` (sin^2 + cos^2 = 1 for theta/2, det M = 0).
  real D1, sigma;
  lrchain::model_evaluator::consistent_half_angle(D1_in, sigma_in, D1, sigma);
  real w[3];
  dispersion_extended(D1, sigma, Q, w);
  const real omega = lrchain::model_evaluator::polished_omega(w, 2, omega_in);
  real o[10];
  o[0] = 0.0;
  const real t0 = (D1 * D1);
  const real t1 = (Q[3] * Q[3]);
  const real t2 = -(t0 * t1);
  const real t3 = (omega * omega);
  const real t4 = (omega * omega * omega * omega);
  const real t5 = -(D1);
  const real t6 = (t5 + 4.0);
  const real t7 = (Q[3] * Q[3] * Q[3]);
  const real t8 = (omega * omega * omega * omega * omega * omega);
  o[1] = -(2.0 * (-(t0 * t7) - (2.0 * t4 * Q[3]) - (8.0 * t4 * Q[2] * Q[3]) + 2.0 * t1 * t3 * D1 + 2.0 * t7 * D1 + 4.0 * t8 * Q[2]) * Q[4] * sigma / ((t2 - (8.0 * t3 * Q[2] * Q[3]) - (8.0 * t3 * Q[3]) + 16.0 * t4 * Q[2] + 4.0 * t1 * D1) * t6 * (Q[3] * Q[3])));
  o[2] = 0.0;
  o[3] = 0.0;
  o[4] = 0.0;
  const real t9 = (-(t4 * D1) - (2.0 * t1 * D1) - (6.0 * t4) + 6.0 * t3 * D1 * Q[3]);
  o[5] = -((real(1.0) / 2.0) * t9 * D1 * Q[4] / ((t2 - (8.0 * t3 * Q[2] * Q[3]) - (8.0 * t3 * Q[3]) + 16.0 * t4 * Q[2] + 4.0 * t1 * D1) * Q[3]));
  o[6] = t9 * (t5 + 2.0) * Q[4] * sigma / ((t2 - (8.0 * t3 * Q[2] * Q[3]) - (8.0 * t3 * Q[3]) + 16.0 * t4 * Q[2] + 4.0 * t1 * D1) * t6 * Q[3]);
  const real t10 = (Q[2] * Q[2]);
  const real t11 = (Q[3] * Q[3] * Q[3] * Q[3]);
  const real t12 = (Q[3] * Q[3] * Q[3] * Q[3] * Q[3]);
  const real t13 = (-(t1 * D1) - (4.0 * t3 * Q[2] * Q[3]) + t4 * Q[2] + 4.0 * t1 + 4.0 * t1 * Q[2]);
  o[7] = 4.0 * (t13 * t13) * (t4 - (t3 * D1 * Q[3]) + t1 * D1) * t3 * Q[4] / ((-(t0 * t7 * t4) - (t0 * t7 * t4 * Q[2]) - (12.0 * t7 * t4 * D1 * Q[2]) - (16.0 * t1 * t8 * Q[2]) - (2.0 * t10 * (omega * omega * omega * omega * omega * omega * omega * omega * omega * omega)) - (32.0 * t10 * t11 * t3) - (32.0 * t11 * t3) - (4.0 * t0 * t12) - (4.0 * t0 * t12 * Q[2]) - (48.0 * t10 * t1 * t8) - (64.0 * t11 * t3 * Q[2]) + 16.0 * t10 * (omega * omega * omega * omega * omega * omega * omega * omega) * Q[3] + 16.0 * t12 * D1 + 16.0 * t12 * D1 * Q[2] + 2.0 * t0 * t11 * t3 + 4.0 * t0 * t11 * t3 * Q[2] + 4.0 * t1 * t8 * D1 * Q[2] + 4.0 * t7 * t4 * D1 + 64.0 * t10 * t7 * t4 + 64.0 * t7 * t4 * Q[2]) * t6 * (Q[3] * Q[3] * Q[3]));
  o[8] = -((real(1.0) / 2.0) * (t2 - (2.0 * t4 * Q[2]) - (8.0 * t1) - (8.0 * t1 * Q[2]) + 6.0 * t1 * D1 + 8.0 * t3 * Q[2] * Q[3]) * Q[3] / (t13 * (-(t3 * Q[2]) + 2.0 * Q[3])));
  o[9] = t6 * t7 * sigma / (t13 * (-(t3 * Q[2]) + 2.0 * Q[3]));
  for (int k = 0; k < 10; ++k) out[k] = static_cast<double>(o[k]);
}

// The model's description for lrchain::Model (parameters, ranges, branches, evaluators).
inline lrchain::ModelDefinition definition() {
  lrchain::ModelDefinition d;
  d.name = "diatomic_chain";
  d.description = "diatomic granular chain with precompression (alternating masses 1 and m)";
  d.file_hash = 0xe672bce94294c28bull;
  d.file_sha256 = "55f97d6d66103d8ed722e92c80204e3a95f965681f9dae7edcdfa218ba01bd79";
  d.parameters.push_back({"alpha", "(1, inf)", 1.5, true, false, false, false, 1, 0});
  d.parameters.push_back({"delta0", "(0, inf)", 0.44444444444444442, true, false, false, false, 0, 0});
  d.parameters.push_back({"m", "(0, inf)", 2, true, false, false, false, 0, 0});
  d.intermediates.push_back("K2");
  d.intermediates.push_back("K3");
  d.intermediates.push_back("K4");
  d.branch_names.push_back("acoustic");
  d.branch_names.push_back("optical");
  d.mean_flow = true;
  d.degree = 2;
  d.evaluators = {&intermediates, &dispersion, &nls, &harmonics, nullptr};
  return d;
}

}  // namespace lrchain::generated::model_diatomic_chain
