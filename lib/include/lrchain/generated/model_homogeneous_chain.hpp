// GENERATED FILE - DO NOT EDIT.
// Written by lrchain-derive from models/homogeneous_chain.toml (FNV-1a 64 0xda8db417c80f8ee3): the double evaluators of
// the model's dispersion relation and NLS coefficients (docs/models.md).
// Regenerate with `cmake --build build --target regenerate`.
#pragma once

#include <cmath>

#include "lrchain/model.hpp"

namespace lrchain::generated::model_homogeneous_chain {

// q = the parameters p, then the named intermediates of the force laws.
inline void intermediates(const double* p, double* q) noexcept {
  q[0] = p[0];
  q[1] = p[1];
  const double t0 = std::pow(p[1], p[0]);
  q[2] = p[0] * t0 / (p[1]);
  const double t1 = (p[0] * p[0]);
  q[3] = (-((1.0 / 2.0) * t1 * t0 / ((p[1] * p[1]))) + (1.0 / 2.0) * p[0] * t0 / ((p[1] * p[1])));
  q[4] = (-((1.0 / 2.0) * t1 * t0 / ((p[1] * p[1] * p[1]))) + (1.0 / 3.0) * p[0] * t0 / ((p[1] * p[1] * p[1])) + (1.0 / 6.0) * (p[0] * p[0] * p[0]) * t0 / ((p[1] * p[1] * p[1])));
}

// Coefficients of det M = 0 in ascending powers of omega^2 at D1 = 4 sin^2(theta/2), sigma = sin(theta).
inline void dispersion(double D1, double sigma, const double* q, double* w) noexcept {
  (void)sigma;
  (void)q;
  w[0] = D1 * q[2];
  w[1] = (-1.0);
}

// NLS coefficients at omega on a branch of det M = 0 (outputs in lrchain::ModelOutput order).
inline void nls(double D1, double sigma, double omega, const double* q, double* out) noexcept {
  (void)sigma;
  (void)q;
  out[0] = q[2] * sigma / (omega);
  const double t0 = (1.0 / omega);
  out[1] = t0;
  const double t1 = -(D1 * q[2]);
  const double t2 = (out[0] * out[0]);
  out[2] = (1.0 / 2.0) * (t1 - (2.0 * t2) + 2.0 * q[2]) * out[1];
  out[3] = -(D1 * out[1] * q[3]);
  const double t3 = (D1 * D1);
  const double t4 = (omega * omega);
  out[4] = -((-(t3 * q[2]) - (4.0 * t4) + 4.0 * D1 * q[2]));
  const double t5 = -(q[2]);
  out[5] = (t2 + t5);
  const double t6 = (q[3] * q[3]);
  out[6] = -((1.0 / 2.0) * (-(12.0 * t4 * q[4]) - (3.0 * t3 * q[2] * q[4]) - (8.0 * t6 * D1) + 12.0 * D1 * q[2] * q[4] + 2.0 * t3 * t6) * t3 * out[1] / (out[4]));
  out[7] = 2.0 * D1 * q[3] / (out[5]);
  out[8] = (-(out[3] * out[7]) + out[6]);
  const double t7 = (D1 * D1 * D1);
  out[9] = (1.0 / 2.0) * (-(12.0 * t3 * out[1] * out[5] * q[2] * q[4]) - (2.0 * t7 * t6 * out[1] * out[5]) - (4.0 * out[3] * out[4] * q[3]) + 12.0 * t4 * D1 * out[1] * out[5] * q[4] + 3.0 * t7 * out[1] * out[5] * q[2] * q[4] + 8.0 * t3 * t6 * out[1] * out[5]) * D1;
  out[10] = -((t4 + t1));
  out[11] = (std::abs(-(4.0 * D1 * q[2])) + std::abs(t3 * q[2]) + std::abs(4.0 * t4));
  out[12] = (std::abs(t2) + std::abs(t5));
}

// The model's description for lrchain::Model (parameters, ranges, branches, evaluators).
inline lrchain::ModelDefinition definition() {
  lrchain::ModelDefinition d;
  d.name = "homogeneous_chain";
  d.description = "homogeneous granular chain with precompression (Hertz contacts)";
  d.file_hash = 0xda8db417c80f8ee3ull;
  d.parameters.push_back({"alpha", "(1, inf)", 1.5, true, false, false, false, 1, 0});
  d.parameters.push_back({"delta0", "(0, inf)", 0.44444444444444442, true, false, false, false, 0, 0});
  d.intermediates.push_back("K2");
  d.intermediates.push_back("K3");
  d.intermediates.push_back("K4");
  d.branch_names.push_back("acoustic");
  d.mean_flow = true;
  d.degree = 1;
  d.evaluators = {&intermediates, &dispersion, &nls};
  return d;
}

}  // namespace lrchain::generated::model_homogeneous_chain
