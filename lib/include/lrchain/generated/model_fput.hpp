// GENERATED FILE - DO NOT EDIT.
// Written by lrchain-derive from models/fput.toml (FNV-1a 64 0x5b104df96318551e): the double evaluators of
// the model's dispersion relation and NLS coefficients (docs/models.md).
// Regenerate with `cmake --build build --target regenerate`.
#pragma once

#include <cmath>

#include "lrchain/model.hpp"
#include "lrchain/model_evaluator_support.hpp"

namespace lrchain::generated::model_fput {

// q = the parameters p, then the named intermediates of the force laws.
inline void intermediates(const double* p, double* q) noexcept {
  q[0] = p[0];
  q[1] = p[1];
}

// Coefficients of det M = 0 in ascending powers of omega^2 at D1 = 4 sin^2(theta/2), sigma = sin(theta).
inline void dispersion(double D1, double sigma, const double* q, double* w) noexcept {
  (void)sigma;
  (void)q;
  w[0] = D1;
  w[1] = (-1.0);
}

// intermediates() in long double.
inline void intermediates_extended(const long double* p, long double* q) noexcept {
  using real [[maybe_unused]] = long double;
  q[0] = p[0];
  q[1] = p[1];
}

// Coefficients of det M as dispersion(), in long double arithmetic.
inline void dispersion_extended(long double D1, long double sigma, const long double* Q, long double* w) noexcept {
  using real [[maybe_unused]] = long double;
  (void)sigma;
  (void)Q;
  w[0] = D1;
  w[1] = (-1.0);
}

// NLS coefficients at omega on a branch of det M = 0 (outputs in lrchain::ModelOutput order). In long double: the terms of its factors cancel by up to 8.1e+05 (measured at derivation).
inline void nls(double D1_in, double sigma_in, double omega_in, const double* q, double* out) noexcept {
  using real [[maybe_unused]] = long double;
  using lrchain::model_evaluator::magnitude;
  long double parameters[2], intermediates[2];
  lrchain::model_evaluator::widen(q, parameters, 2);
  intermediates_extended(parameters, intermediates);
  real Q[2];
  lrchain::model_evaluator::widen(intermediates, Q, 2);
  // D1, sigma and omega consistent in `real` (sin^2 + cos^2 = 1 for theta/2, det M = 0).
  real D1, sigma;
  lrchain::model_evaluator::consistent_half_angle(D1_in, sigma_in, D1, sigma);
  real w[2];
  dispersion_extended(D1, sigma, Q, w);
  const real omega = lrchain::model_evaluator::polished_omega(w, 1, omega_in);
  real o[13];
  o[0] = sigma / (omega);
  const real t0 = (1.0 / omega);
  o[1] = t0;
  const real t1 = -(D1);
  const real t2 = (o[0] * o[0]);
  o[2] = (real(1.0) / 2.0) * (t1 - (2.0 * t2) + 2.0) * o[1];
  o[3] = -(D1 * Q[0] * o[1]);
  const real t3 = (D1 * D1);
  const real t4 = -(4.0 * D1);
  const real t5 = (omega * omega);
  const real t6 = 4.0 * t5;
  o[4] = (t3 + t4 + t6);
  const real t7 = -(o[0]);
  o[5] = (t7 + 1.0) * ((-1.0) + t7);
  const real t8 = (Q[0] * Q[0]);
  o[6] = -((real(1.0) / 2.0) * (-(12.0 * t5 * Q[1]) - (3.0 * t3 * Q[1]) - (8.0 * t8 * D1) + 12.0 * D1 * Q[1] + 2.0 * t3 * t8) * t3 * o[1] / (o[4]));
  o[7] = 2.0 * D1 * Q[0] / (o[5]);
  o[8] = (-(o[3] * o[7]) + o[6]);
  const real t9 = (D1 * D1 * D1);
  o[9] = (real(1.0) / 2.0) * (-(12.0 * t3 * Q[1] * o[1] * o[5]) - (2.0 * t9 * t8 * o[1] * o[5]) - (4.0 * Q[0] * o[3] * o[4]) + 12.0 * t5 * D1 * Q[1] * o[1] * o[5] + 3.0 * t9 * Q[1] * o[1] * o[5] + 8.0 * t3 * t8 * o[1] * o[5]) * D1;
  o[10] = -((t5 + t1));
  o[11] = (magnitude(t3) + magnitude(t4) + magnitude(t6));
  o[12] = (magnitude(t2) + magnitude((-1.0)));
  for (int k = 0; k < 13; ++k) out[k] = static_cast<double>(o[k]);
}

// Per field f, out[5f..5f+4]: second harmonic A_{2,2,f}/A_{1,1}^2 (real, imaginary part), mean A_{2,0,f}/|A_{1,1}|^2, gradient term of A_{2,1,f} per d_xi A_{1,1} (real, imaginary) (lrchain::HarmonicOutput).
inline void harmonics(double D1_in, double sigma_in, double omega_in, const double* q, double* out) noexcept {
  using real [[maybe_unused]] = long double;
  [[maybe_unused]] const auto magnitude = [](real x) { return x < 0 ? -x : x; };
  long double parameters[2], intermediates[2];
  lrchain::model_evaluator::widen(q, parameters, 2);
  intermediates_extended(parameters, intermediates);
  real Q[2];
  lrchain::model_evaluator::widen(intermediates, Q, 2);
  // D1, sigma and omega consistent in `real` (sin^2 + cos^2 = 1 for theta/2, det M = 0).
  real D1, sigma;
  lrchain::model_evaluator::consistent_half_angle(D1_in, sigma_in, D1, sigma);
  real w[2];
  dispersion_extended(D1, sigma, Q, w);
  const real omega = lrchain::model_evaluator::polished_omega(w, 1, omega_in);
  real o[5];
  o[0] = 0.0;
  o[1] = 2.0 * D1 * Q[0] * sigma / (((D1 * D1) - (4.0 * D1) + 4.0 * (omega * omega)));
  o[2] = 0.0;
  o[3] = 0.0;
  o[4] = 0.0;
  for (int k = 0; k < 5; ++k) out[k] = static_cast<double>(o[k]);
}

// The model's description for lrchain::Model (parameters, ranges, branches, evaluators).
inline lrchain::ModelDefinition definition() {
  lrchain::ModelDefinition d;
  d.name = "fput";
  d.description = "Fermi-Pasta-Ulam-Tsingou chain, F(r) = r + a r^2 + b r^3";
  d.file_hash = 0x5b104df96318551eull;
  d.file_sha256 = "86c9509c74b41ccb40cc5f2e683d3285b3974ca32ae45e05e7d84a0b3eb05fb8";
  d.parameters.push_back({"a", "(-inf, inf)", 0.25, false, false, false, false, 0, 0});
  d.parameters.push_back({"b", "(-inf, inf)", 0.5, false, false, false, false, 0, 0});
  d.branch_names.push_back("acoustic");
  d.mean_flow = true;
  d.degree = 1;
  d.evaluators = {&intermediates, &dispersion, &nls, &harmonics, nullptr};
  return d;
}

}  // namespace lrchain::generated::model_fput
