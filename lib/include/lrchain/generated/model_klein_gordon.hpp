// GENERATED FILE - DO NOT EDIT.
// Written by lrchain-derive from models/klein_gordon.toml (FNV-1a 64 0x82ca43664d77dcab): the double evaluators of
// the model's dispersion relation and NLS coefficients (docs/models.md).
// Regenerate with `cmake --build build --target regenerate`.
#pragma once

#include <cmath>

#include "lrchain/model.hpp"
#include "lrchain/model_evaluator_support.hpp"

namespace lrchain::generated::model_klein_gordon {

// q = the parameters p, then the named intermediates of the force laws.
inline void intermediates(const double* p, double* q) noexcept {
  q[0] = p[0];
  q[1] = p[1];
  q[2] = p[2];
  q[3] = p[3];
}

// Coefficients of det M = 0 in ascending powers of omega^2 at D1 = 4 sin^2(theta/2), sigma = sin(theta).
inline void dispersion(double D1, double sigma, const double* q, double* w) noexcept {
  (void)sigma;
  (void)q;
  w[0] = ((q[1] * q[1]) + D1 * q[0]);
  w[1] = (-1.0);
}

// intermediates() in long double.
inline void intermediates_extended(const long double* p, long double* q) noexcept {
  using real [[maybe_unused]] = long double;
  q[0] = p[0];
  q[1] = p[1];
  q[2] = p[2];
  q[3] = p[3];
}

// Coefficients of det M as dispersion(), in long double arithmetic.
inline void dispersion_extended(long double D1, long double sigma, const long double* Q, long double* w) noexcept {
  using real [[maybe_unused]] = long double;
  (void)sigma;
  (void)Q;
  w[0] = ((Q[1] * Q[1]) + D1 * Q[0]);
  w[1] = (-1.0);
}

// NLS coefficients at omega on a branch of det M = 0 (outputs in lrchain::ModelOutput order). In long double: the terms of its factors cancel by up to 4.1 (measured at derivation).
inline void nls(double D1_in, double sigma_in, double omega_in, const double* q, double* out) noexcept {
  using real [[maybe_unused]] = long double;
  using lrchain::model_evaluator::magnitude;
  long double parameters[4], intermediates[4];
  lrchain::model_evaluator::widen(q, parameters, 4);
  intermediates_extended(parameters, intermediates);
  real Q[4];
  lrchain::model_evaluator::widen(intermediates, Q, 4);
  // D1, sigma and omega consistent in `real` (sin^2 + cos^2 = 1 for theta/2, det M = 0).
  real D1, sigma;
  lrchain::model_evaluator::consistent_half_angle(D1_in, sigma_in, D1, sigma);
  real w[2];
  dispersion_extended(D1, sigma, Q, w);
  const real omega = lrchain::model_evaluator::polished_omega(w, 1, omega_in);
  real o[13];
  o[0] = Q[0] * sigma / (omega);
  const real t0 = (1.0 / omega);
  o[1] = t0;
  o[2] = (real(1.0) / 2.0) * (-(D1 * Q[0]) - (2.0 * (o[0] * o[0])) + 2.0 * Q[0]) * o[1];
  o[3] = 0.0;
  const real t1 = (Q[1] * Q[1]);
  const real t2 = (D1 * D1);
  const real t3 = -(t2 * Q[0]);
  const real t4 = (omega * omega);
  const real t5 = -(4.0 * t4);
  const real t6 = 4.0 * D1 * Q[0];
  o[4] = -((t1 + t3 + t5 + t6));
  o[5] = 1.0;
  const real t7 = (Q[2] * Q[2]);
  const real t8 = (-(12.0 * t1 * t4 * Q[3]) - (16.0 * t7 * D1 * Q[0]) - (3.0 * t2 * t1 * Q[0] * Q[3]) - (6.0 * t1 * t7) + 12.0 * t1 * D1 * Q[0] * Q[3] + 16.0 * t7 * t4 + 3.0 * (Q[1] * Q[1] * Q[1] * Q[1]) * Q[3] + 4.0 * t2 * t7 * Q[0]);
  o[6] = -((real(1.0) / 2.0) * t8 * o[1] / ((Q[1] * Q[1]) * o[4]));
  o[7] = 0.0;
  o[8] = (-(o[3] * o[7]) + o[6]);
  o[9] = -((real(1.0) / 2.0) * t8 * o[1] * o[5] / ((Q[1] * Q[1])));
  o[10] = (t1 - (t4) + D1 * Q[0]);
  o[11] = (magnitude(t1) + magnitude(t3) + magnitude(t5) + magnitude(t6));
  o[12] = magnitude(1.0);
  for (int k = 0; k < 13; ++k) out[k] = static_cast<double>(o[k]);
}

// Per field f, out[5f..5f+4]: second harmonic A_{2,2,f}/A_{1,1}^2 (real, imaginary part), mean A_{2,0,f}/|A_{1,1}|^2, gradient term of A_{2,1,f} per d_xi A_{1,1} (real, imaginary) (lrchain::HarmonicOutput).
inline void harmonics(double D1_in, double sigma_in, double omega_in, const double* q, double* out) noexcept {
  using real [[maybe_unused]] = long double;
  [[maybe_unused]] const auto magnitude = [](real x) { return x < 0 ? -x : x; };
  long double parameters[4], intermediates[4];
  lrchain::model_evaluator::widen(q, parameters, 4);
  intermediates_extended(parameters, intermediates);
  real Q[4];
  lrchain::model_evaluator::widen(intermediates, Q, 4);
  // D1, sigma and omega consistent in `real` (sin^2 + cos^2 = 1 for theta/2, det M = 0).
  real D1, sigma;
  lrchain::model_evaluator::consistent_half_angle(D1_in, sigma_in, D1, sigma);
  real w[2];
  dispersion_extended(D1, sigma, Q, w);
  const real omega = lrchain::model_evaluator::polished_omega(w, 1, omega_in);
  real o[5];
  o[0] = -(Q[2] / (((Q[1] * Q[1]) - ((D1 * D1) * Q[0]) - (4.0 * (omega * omega)) + 4.0 * D1 * Q[0])));
  o[1] = 0.0;
  o[2] = -(2.0 * Q[2] / ((Q[1] * Q[1])));
  o[3] = 0.0;
  o[4] = 0.0;
  for (int k = 0; k < 5; ++k) out[k] = static_cast<double>(o[k]);
}

// The model's description for lrchain::Model (parameters, ranges, branches, evaluators).
inline lrchain::ModelDefinition definition() {
  lrchain::ModelDefinition d;
  d.name = "klein_gordon";
  d.description = "discrete Klein-Gordon chain with an anharmonic on-site force";
  d.file_hash = 0x82ca43664d77dcabull;
  d.file_sha256 = "a45b1b1347353afdbbfaab0915b77a7890fbb9b83de4a8224b0772235e934b6c";
  d.parameters.push_back({"C", "[0, inf)", 0.10000000000000001, true, false, true, false, 0, 0});
  d.parameters.push_back({"w0", "(0, inf)", 1, true, false, false, false, 0, 0});
  d.parameters.push_back({"a", "(-inf, inf)", 0.25, false, false, false, false, 0, 0});
  d.parameters.push_back({"b", "(-inf, inf)", 0.5, false, false, false, false, 0, 0});
  d.branch_names.push_back("branch0");
  d.mean_flow = false;
  d.degree = 1;
  d.evaluators = {&intermediates, &dispersion, &nls, &harmonics, nullptr};
  return d;
}

}  // namespace lrchain::generated::model_klein_gordon
