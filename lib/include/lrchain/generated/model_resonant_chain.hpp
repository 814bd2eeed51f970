// GENERATED FILE - DO NOT EDIT.
// Written by lrchain-derive from models/resonant_chain.toml (FNV-1a 64 0x505810b6d7d1235f): the double evaluators of
// the model's dispersion relation and NLS coefficients (docs/models.md).
// Regenerate with `cmake --build build --target regenerate`.
#pragma once

#include <cmath>

#include "lrchain/model.hpp"

namespace lrchain::generated::model_resonant_chain {

// q = the parameters p, then the named intermediates of the force laws.
inline void intermediates(const double* p, double* q) noexcept {
  q[0] = p[0];
  q[1] = p[1];
  q[2] = p[2];
  q[3] = p[3];
  const double t0 = std::pow(p[1], p[0]);
  q[4] = p[0] * t0 / (p[1]);
  const double t1 = (p[0] * p[0]);
  q[5] = (-((1.0 / 2.0) * t1 * t0 / ((p[1] * p[1]))) + (1.0 / 2.0) * p[0] * t0 / ((p[1] * p[1])));
  q[6] = (-((1.0 / 2.0) * t1 * t0 / ((p[1] * p[1] * p[1]))) + (1.0 / 3.0) * p[0] * t0 / ((p[1] * p[1] * p[1])) + (1.0 / 6.0) * (p[0] * p[0] * p[0]) * t0 / ((p[1] * p[1] * p[1])));
}

// Coefficients of det M = 0 in ascending powers of omega^2 at D1 = 4 sin^2(theta/2), sigma = sin(theta).
inline void dispersion(double D1, double sigma, const double* q, double* w) noexcept {
  (void)sigma;
  (void)q;
  w[0] = D1 * q[2] * q[4];
  w[1] = (-(D1 * q[3] * q[4]) - (q[2]) - (q[2] * q[3]));
  w[2] = q[3];
}

// NLS coefficients at omega on a branch of det M = 0 (outputs in lrchain::ModelOutput order).
inline void nls(double D1, double sigma, double omega, const double* q, double* out) noexcept {
  (void)sigma;
  (void)q;
  const double t0 = (q[2] * q[2]);
  const double t1 = (omega * omega);
  const double t2 = (omega * omega * omega * omega);
  const double t3 = (q[3] * q[3]);
  const double t4 = (-(t1 * q[3]) + q[2]);
  const double t5 = (t4 * t4);
  out[0] = t5 * q[4] * sigma / ((t0 - (2.0 * t1 * q[2] * q[3]) + t2 * t3 + t0 * q[3]) * omega);
  out[1] = t5 / ((t0 - (2.0 * t1 * q[2] * q[3]) + t2 * t3 + t0 * q[3]) * omega);
  const double t6 = (omega * omega * omega * omega * omega * omega);
  const double t7 = (q[3] * q[3] * q[3]);
  const double t8 = (out[0] * out[0]);
  const double t9 = (q[2] * q[2] * q[2]);
  out[2] = -((1.0 / 2.0) * (-(t6 * t7 * D1 * q[4]) - (2.0 * t6 * t8 * t7) - (2.0 * t9 * q[4]) - (3.0 * t1 * t0 * D1 * q[3] * q[4]) - (6.0 * t1 * t8 * t0 * q[3]) - (6.0 * t2 * t3 * q[2] * q[4]) + t9 * D1 * q[4] + 2.0 * t6 * t7 * q[4] + 2.0 * t8 * t9 + 2.0 * t8 * t9 * q[3] + 3.0 * t2 * t3 * D1 * q[2] * q[4] + 6.0 * t1 * t8 * t0 * t3 + 6.0 * t1 * t0 * q[3] * q[4] + 6.0 * t2 * t8 * t3 * q[2]) * out[1] / ((t4 * t4 * t4)));
  out[3] = -(D1 * out[1] * q[5]);
  const double t10 = (D1 * D1);
  out[4] = -((-(t10 * q[2] * q[4]) - (16.0 * t1 * D1 * q[3] * q[4]) - (4.0 * t1 * q[2]) - (4.0 * t1 * q[2] * q[3]) + 16.0 * t2 * q[3] + 4.0 * t10 * t1 * q[3] * q[4] + 4.0 * D1 * q[2] * q[4]));
  const double t11 = -(q[4]);
  const double t12 = t8 * q[3];
  out[5] = (t8 + t11 + t12);
  const double t13 = (q[5] * q[5]);
  out[6] = (1.0 / 2.0) * (-(12.0 * t10 * t1 * q[3] * q[4] * q[6]) - (12.0 * D1 * q[2] * q[4] * q[6]) - (2.0 * t10 * t13 * q[2]) - (32.0 * t1 * t13 * D1 * q[3]) - (48.0 * t2 * q[3] * q[6]) + 12.0 * t1 * q[2] * q[3] * q[6] + 12.0 * t1 * q[2] * q[6] + 3.0 * t10 * q[2] * q[4] * q[6] + 48.0 * t1 * D1 * q[3] * q[4] * q[6] + 8.0 * t10 * t1 * t13 * q[3] + 8.0 * t13 * D1 * q[2]) * t10 * out[1] / (out[4]);
  out[7] = 2.0 * D1 * q[5] / (out[5]);
  out[8] = (-(out[3] * out[7]) + out[6]);
  const double t14 = (D1 * D1 * D1);
  out[9] = (1.0 / 2.0) * (-(12.0 * t10 * out[1] * out[5] * q[2] * q[4] * q[6]) - (12.0 * t14 * t1 * out[1] * out[5] * q[3] * q[4] * q[6]) - (2.0 * t14 * t13 * out[1] * out[5] * q[2]) - (32.0 * t10 * t1 * t13 * out[1] * out[5] * q[3]) - (4.0 * out[3] * out[4] * q[5]) - (48.0 * t2 * D1 * out[1] * out[5] * q[3] * q[6]) + 12.0 * t1 * D1 * out[1] * out[5] * q[2] * q[3] * q[6] + 12.0 * t1 * D1 * out[1] * out[5] * q[2] * q[6] + 3.0 * t14 * out[1] * out[5] * q[2] * q[4] * q[6] + 48.0 * t10 * t1 * out[1] * out[5] * q[3] * q[4] * q[6] + 8.0 * t10 * t13 * out[1] * out[5] * q[2] + 8.0 * t14 * t1 * t13 * out[1] * out[5] * q[3]) * D1;
  out[10] = (-(t1 * D1 * q[3] * q[4]) - (t1 * q[2]) - (t1 * q[2] * q[3]) + t2 * q[3] + D1 * q[2] * q[4]);
  out[11] = (std::abs(-(16.0 * t2 * q[3])) + std::abs(-(4.0 * t10 * t1 * q[3] * q[4])) + std::abs(-(4.0 * D1 * q[2] * q[4])) + std::abs(t10 * q[2] * q[4]) + std::abs(16.0 * t1 * D1 * q[3] * q[4]) + std::abs(4.0 * t1 * q[2]) + std::abs(4.0 * t1 * q[2] * q[3]));
  out[12] = (std::abs(t8) + std::abs(t11) + std::abs(t12));
}

// The model's description for lrchain::Model (parameters, ranges, branches, evaluators).
inline lrchain::ModelDefinition definition() {
  lrchain::ModelDefinition d;
  d.name = "resonant_chain";
  d.description = "locally resonant granular chain with precompression (Hertz contacts, linear resonators)";
  d.file_hash = 0x505810b6d7d1235full;
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
  d.evaluators = {&intermediates, &dispersion, &nls};
  return d;
}

}  // namespace lrchain::generated::model_resonant_chain
