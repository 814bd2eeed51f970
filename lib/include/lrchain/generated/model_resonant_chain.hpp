// GENERATED FILE - DO NOT EDIT.
// Written by lrchain-derive from models/resonant_chain.toml (FNV-1a 64 0x505810b6d7d1235f): the double evaluators of
// the model's dispersion relation and NLS coefficients (docs/models.md).
// Regenerate with `cmake --build build --target regenerate`.
#pragma once

#include <cmath>

#include "lrchain/model.hpp"
#include "lrchain/model_evaluator_support.hpp"

namespace lrchain::generated::model_resonant_chain {

// q = the parameters p, then the named intermediates of the force laws.
inline void intermediates(const double* p, double* q) noexcept {
  q[0] = p[0];
  q[1] = p[1];
  q[2] = p[2];
  q[3] = p[3];
  const double t0 = std::pow(p[1], p[0]);
  q[4] = p[0] * t0 / (p[1]);
  const double t1 = -(p[0]);
  const double t2 = (t1 + 1.0);
  q[5] = (1.0 / 2.0) * t2 * p[0] * t0 / ((p[1] * p[1]));
  q[6] = (1.0 / 6.0) * t2 * (t1 + 2.0) * p[0] * t0 / ((p[1] * p[1] * p[1]));
}

// Coefficients of det M = 0 in ascending powers of omega^2 at D1 = 4 sin^2(theta/2), sigma = sin(theta).
inline void dispersion(double D1, double sigma, const double* q, double* w) noexcept {
  (void)sigma;
  (void)q;
  w[0] = D1 * q[2] * q[4];
  w[1] = (-(D1 * q[3] * q[4]) - (q[2]) - (q[2] * q[3]));
  w[2] = q[3];
}

// Coefficients of det M as dispersion(), in long double arithmetic.
inline void dispersion_extended(long double D1, long double sigma, const long double* Q, long double* w) noexcept {
  using real [[maybe_unused]] = long double;
  (void)sigma;
  (void)Q;
  w[0] = D1 * Q[2] * Q[4];
  w[1] = (-(D1 * Q[3] * Q[4]) - (Q[2]) - (Q[2] * Q[3]));
  w[2] = Q[3];
}

// nls() in long double from consistent inputs, where the double nls loses digits.
inline void nls_extended(double D1_in, double sigma_in, double omega_in, const double* q, double* out) noexcept {
  using real [[maybe_unused]] = long double;
  using lrchain::model_evaluator::magnitude;
  real Q[7];
  lrchain::model_evaluator::widen(q, Q, 7);
  // D1, sigma and omega consistent in `real` (sin^2 + cos^2 = 1 for theta/2, det M = 0).
  real D1, sigma;
  lrchain::model_evaluator::consistent_half_angle(D1_in, sigma_in, D1, sigma);
  real w[3];
  dispersion_extended(D1, sigma, Q, w);
  const real omega = lrchain::model_evaluator::polished_omega(w, 2, omega_in);
  real o[13];
  const real t0 = (Q[2] * Q[2]);
  const real t1 = (omega * omega);
  const real t2 = (Q[3] * Q[3]);
  const real t3 = (omega * omega * omega * omega);
  const real t4 = (-(t1 * Q[3]) + Q[2]);
  const real t5 = (t4 * t4);
  o[0] = t5 * Q[4] * sigma / ((t0 - (2.0 * t1 * Q[2] * Q[3]) + t0 * Q[3] + t2 * t3) * omega);
  o[1] = t5 / ((t0 - (2.0 * t1 * Q[2] * Q[3]) + t0 * Q[3] + t2 * t3) * omega);
  const real t6 = (Q[2] * Q[2] * Q[2]);
  const real t7 = (o[0] * o[0]);
  const real t8 = (Q[3] * Q[3] * Q[3]);
  const real t9 = (omega * omega * omega * omega * omega * omega);
  o[2] = (real(1.0) / 2.0) * (-(t6 * D1 * Q[4]) - (2.0 * t6 * t7) - (2.0 * t6 * t7 * Q[3]) - (2.0 * t8 * t9 * Q[4]) - (3.0 * t2 * t3 * D1 * Q[2] * Q[4]) - (6.0 * t0 * t2 * t7 * t1) - (6.0 * t0 * t1 * Q[3] * Q[4]) - (6.0 * t2 * t7 * t3 * Q[2]) + t8 * t9 * D1 * Q[4] + 2.0 * t6 * Q[4] + 2.0 * t8 * t7 * t9 + 3.0 * t0 * t1 * D1 * Q[3] * Q[4] + 6.0 * t0 * t7 * t1 * Q[3] + 6.0 * t2 * t3 * Q[2] * Q[4]) * o[1] / ((t4 * t4 * t4));
  o[3] = -(D1 * Q[5] * o[1]);
  const real t10 = (D1 * D1);
  const real t11 = -(t10 * Q[2] * Q[4]);
  const real t12 = -(16.0 * t1 * D1 * Q[3] * Q[4]);
  const real t13 = -(4.0 * t1 * Q[2]);
  const real t14 = -(4.0 * t1 * Q[2] * Q[3]);
  const real t15 = 16.0 * t3 * Q[3];
  const real t16 = 4.0 * t10 * t1 * Q[3] * Q[4];
  const real t17 = 4.0 * D1 * Q[2] * Q[4];
  o[4] = -((t11 + t12 + t13 + t14 + t15 + t16 + t17));
  const real t18 = -(Q[4]);
  const real t19 = t7 * Q[3];
  o[5] = (t7 + t18 + t19);
  const real t20 = (Q[5] * Q[5]);
  o[6] = (real(1.0) / 2.0) * (-(12.0 * t10 * t1 * Q[3] * Q[4] * Q[6]) - (12.0 * D1 * Q[2] * Q[4] * Q[6]) - (2.0 * t10 * t20 * Q[2]) - (32.0 * t20 * t1 * D1 * Q[3]) - (48.0 * t3 * Q[3] * Q[6]) + 12.0 * t1 * Q[2] * Q[3] * Q[6] + 12.0 * t1 * Q[2] * Q[6] + 3.0 * t10 * Q[2] * Q[4] * Q[6] + 48.0 * t1 * D1 * Q[3] * Q[4] * Q[6] + 8.0 * t10 * t20 * t1 * Q[3] + 8.0 * t20 * D1 * Q[2]) * t10 * o[1] / (o[4]);
  o[7] = 2.0 * D1 * Q[5] / (o[5]);
  o[8] = (-(o[3] * o[7]) + o[6]);
  const real t21 = (D1 * D1 * D1);
  o[9] = (real(1.0) / 2.0) * (-(12.0 * t10 * Q[2] * Q[4] * Q[6] * o[1] * o[5]) - (12.0 * t21 * t1 * Q[3] * Q[4] * Q[6] * o[1] * o[5]) - (2.0 * t21 * t20 * Q[2] * o[1] * o[5]) - (32.0 * t10 * t20 * t1 * Q[3] * o[1] * o[5]) - (4.0 * Q[5] * o[3] * o[4]) - (48.0 * t3 * D1 * Q[3] * Q[6] * o[1] * o[5]) + 12.0 * t1 * D1 * Q[2] * Q[3] * Q[6] * o[1] * o[5] + 12.0 * t1 * D1 * Q[2] * Q[6] * o[1] * o[5] + 3.0 * t21 * Q[2] * Q[4] * Q[6] * o[1] * o[5] + 48.0 * t10 * t1 * Q[3] * Q[4] * Q[6] * o[1] * o[5] + 8.0 * t10 * t20 * Q[2] * o[1] * o[5] + 8.0 * t21 * t20 * t1 * Q[3] * o[1] * o[5]) * D1;
  o[10] = (-(t1 * D1 * Q[3] * Q[4]) - (t1 * Q[2]) - (t1 * Q[2] * Q[3]) + t3 * Q[3] + D1 * Q[2] * Q[4]);
  o[11] = (magnitude(t11) + magnitude(t12) + magnitude(t13) + magnitude(t14) + magnitude(t15) + magnitude(t16) + magnitude(t17));
  o[12] = (magnitude(t7) + magnitude(t18) + magnitude(t19));
  for (int k = 0; k < 13; ++k) out[k] = static_cast<double>(o[k]);
}

// NLS coefficients at omega on a branch of det M = 0 (outputs in lrchain::ModelOutput order). omega'' by implicit differentiation of det M; theta < 0.05 in long double (nls_extended).
inline void nls(double D1, double sigma, double omega, const double* q, double* out) noexcept {
  if (D1 < 0.0025) {
    nls_extended(D1, sigma, omega, q, out);
    return;
  }
  (void)sigma;
  (void)q;
  double dispersion_W, dispersion_D, dispersion_WW, dispersion_WD;
  double sum_h, cancellation_h;
  const double t0 = (q[2] * q[2]);
  const double t1 = (omega * omega);
  const double t2 = (omega * omega * omega * omega);
  const double t3 = (-(t1 * q[3]) + q[2]);
  const double t4 = (t3 * t3);
  out[0] = t4 * q[4] * sigma / ((t0 - (2.0 * t1 * q[2] * q[3]) + t2 * (q[3] * q[3]) + t0 * q[3]) * omega);
  out[1] = t4 / ((t0 - (2.0 * t1 * q[2] * q[3]) + t2 * (q[3] * q[3]) + t0 * q[3]) * omega);
  dispersion_W = (-(D1 * q[3] * q[4]) - (q[2]) - (q[2] * q[3]) + 2.0 * t1 * q[3]);
  dispersion_D = t3 * q[4];
  dispersion_WW = 2.0 * q[3];
  dispersion_WD = -(q[3] * q[4]);
  const double t5 = (out[0] * out[0]);
  out[2] = -((1.0 / 2.0) * (-(D1 * dispersion_D) + 2.0 * t5 * dispersion_W + 2.0 * dispersion_D + 4.0 * t1 * t5 * dispersion_WW + 8.0 * dispersion_WD * omega * out[0] * sigma) / (dispersion_W * omega));
  out[3] = -(D1 * out[1] * q[5]);
  const double t6 = (D1 * D1);
  const double t7 = -(t6 * q[2] * q[4]);
  const double t8 = -(16.0 * t1 * D1 * q[3] * q[4]);
  const double t9 = -(4.0 * t1 * q[2]);
  const double t10 = -(4.0 * t1 * q[2] * q[3]);
  const double t11 = 16.0 * t2 * q[3];
  const double t12 = 4.0 * t6 * t1 * q[3] * q[4];
  const double t13 = 4.0 * D1 * q[2] * q[4];
  out[4] = -((t7 + t8 + t9 + t10 + t11 + t12 + t13));
  const double t14 = -(q[4]);
  const double t15 = t5 * q[3];
  out[5] = (t5 + t14 + t15);
  const double t16 = -(12.0 * t6 * t1 * q[3] * q[4] * q[6]);
  const double t17 = -(12.0 * D1 * q[2] * q[4] * q[6]);
  const double t18 = (q[5] * q[5]);
  const double t19 = -(2.0 * t6 * t18 * q[2]);
  const double t20 = -(32.0 * t1 * t18 * D1 * q[3]);
  const double t21 = -(48.0 * t2 * q[3] * q[6]);
  const double t22 = 12.0 * t1 * q[2] * q[3] * q[6];
  const double t23 = 12.0 * t1 * q[2] * q[6];
  const double t24 = 3.0 * t6 * q[2] * q[4] * q[6];
  const double t25 = 48.0 * t1 * D1 * q[3] * q[4] * q[6];
  const double t26 = 8.0 * t6 * t1 * t18 * q[3];
  const double t27 = 8.0 * t18 * D1 * q[2];
  const double t28 = (t16 + t17 + t19 + t20 + t21 + t22 + t23 + t24 + t25 + t26 + t27);
  out[6] = (1.0 / 2.0) * t28 * t6 * out[1] / (out[4]);
  out[7] = 2.0 * D1 * q[5] / (out[5]);
  out[8] = (-(out[3] * out[7]) + out[6]);
  const double t29 = (D1 * D1 * D1);
  out[9] = (1.0 / 2.0) * (-(12.0 * t6 * out[1] * out[5] * q[2] * q[4] * q[6]) - (12.0 * t29 * t1 * out[1] * out[5] * q[3] * q[4] * q[6]) - (2.0 * t29 * t18 * out[1] * out[5] * q[2]) - (32.0 * t6 * t1 * t18 * out[1] * out[5] * q[3]) - (4.0 * out[3] * out[4] * q[5]) - (48.0 * t2 * D1 * out[1] * out[5] * q[3] * q[6]) + 12.0 * t1 * D1 * out[1] * out[5] * q[2] * q[3] * q[6] + 12.0 * t1 * D1 * out[1] * out[5] * q[2] * q[6] + 3.0 * t29 * out[1] * out[5] * q[2] * q[4] * q[6] + 48.0 * t6 * t1 * out[1] * out[5] * q[3] * q[4] * q[6] + 8.0 * t6 * t18 * out[1] * out[5] * q[2] + 8.0 * t29 * t1 * t18 * out[1] * out[5] * q[3]) * D1;
  out[10] = (-(t1 * D1 * q[3] * q[4]) - (t1 * q[2]) - (t1 * q[2] * q[3]) + t2 * q[3] + D1 * q[2] * q[4]);
  out[11] = (std::abs(t7) + std::abs(t8) + std::abs(t9) + std::abs(t10) + std::abs(t11) + std::abs(t12) + std::abs(t13));
  out[12] = (std::abs(t5) + std::abs(t14) + std::abs(t15));
  sum_h = t28;
  cancellation_h = (std::abs(t16) + std::abs(t17) + std::abs(t19) + std::abs(t20) + std::abs(t21) + std::abs(t22) + std::abs(t23) + std::abs(t24) + std::abs(t25) + std::abs(t26) + std::abs(t27));
  // Sums that cancel in double (near a zero of h, or a non-resonance, times the cancellation of
  // h_tilde): long double.
  const double limit = 1e4;
  const double bound = std::abs(out[8]) * limit, terms = std::abs(out[6]) + std::abs(out[3] * out[7]);
  if (!(std::abs(sum_h) * bound > cancellation_h * terms &&
        std::abs(out[4]) * bound > out[11] * terms && std::abs(out[5]) * bound > out[12] * terms))
    nls_extended(D1, sigma, omega, q, out);
}

// Per field f, out[5f..5f+4]: second harmonic A_{2,2,f}/A_{1,1}^2 (real, imaginary part), mean A_{2,0,f}/|A_{1,1}|^2, gradient term of A_{2,1,f} per d_xi A_{1,1} (real, imaginary) (lrchain::HarmonicOutput).
inline void harmonics(double D1_in, double sigma_in, double omega_in, const double* q, double* out) noexcept {
  using real [[maybe_unused]] = long double;
  [[maybe_unused]] const auto magnitude = [](real x) { return x < 0 ? -x : x; };
  real Q[7];
  lrchain::model_evaluator::widen(q, Q, 7);
  // D1, sigma and omega consistent in `real` (sin^2 + cos^2 = 1 for theta/2, det M = 0).
  real D1, sigma;
  lrchain::model_evaluator::consistent_half_angle(D1_in, sigma_in, D1, sigma);
  real w[3];
  dispersion_extended(D1, sigma, Q, w);
  const real omega = lrchain::model_evaluator::polished_omega(w, 2, omega_in);
  real o[10];
  o[0] = 0.0;
  const real t0 = (D1 * D1);
  const real t1 = (omega * omega);
  const real t2 = (omega * omega * omega * omega);
  o[1] = 2.0 * (-(Q[2]) + 4.0 * t1 * Q[3]) * D1 * Q[5] * sigma / ((-(t0 * Q[2] * Q[4]) - (16.0 * t1 * D1 * Q[3] * Q[4]) - (4.0 * t1 * Q[2]) - (4.0 * t1 * Q[2] * Q[3]) + 16.0 * t2 * Q[3] + 4.0 * t0 * t1 * Q[3] * Q[4] + 4.0 * D1 * Q[2] * Q[4]));
  o[2] = 0.0;
  o[3] = 0.0;
  o[4] = 0.0;
  o[5] = 0.0;
  o[6] = -(2.0 * D1 * Q[2] * Q[5] * sigma / ((-(t0 * Q[2] * Q[4]) - (16.0 * t1 * D1 * Q[3] * Q[4]) - (4.0 * t1 * Q[2]) - (4.0 * t1 * Q[2] * Q[3]) + 16.0 * t2 * Q[3] + 4.0 * t0 * t1 * Q[3] * Q[4] + 4.0 * D1 * Q[2] * Q[4])));
  o[7] = 0.0;
  o[8] = 0.0;
  const real t3 = (Q[2] * Q[2]);
  o[9] = -(2.0 * Q[2] * Q[3] * Q[4] * sigma / ((t3 - (2.0 * t1 * Q[2] * Q[3]) + t3 * Q[3] + (Q[3] * Q[3]) * t2)));
  for (int k = 0; k < 10; ++k) out[k] = static_cast<double>(o[k]);
}

// The model's description for lrchain::Model (parameters, ranges, branches, evaluators).
inline lrchain::ModelDefinition definition() {
  lrchain::ModelDefinition d;
  d.name = "resonant_chain";
  d.description = "locally resonant granular chain with precompression (Hertz contacts, linear resonators)";
  d.file_hash = 0x505810b6d7d1235full;
  d.file_sha256 = "2e3879764492a3bc35a8cd17fc98f1317553854db4d0fc1b318641172ec10e83";
  d.parameters.push_back({"alpha", "(1, 5]", 1.5, true, true, false, true, 1, 5});
  d.parameters.push_back({"delta0", "(0, 10]", 0.44444444444444442, true, true, false, true, 0, 10});
  d.parameters.push_back({"kappa", "(0, 10000]", 1, true, true, false, true, 0, 10000});
  d.parameters.push_back({"rho", "(0, 10000]", 0.33333333333333331, true, true, false, true, 0, 10000});
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

}  // namespace lrchain::generated::model_resonant_chain
