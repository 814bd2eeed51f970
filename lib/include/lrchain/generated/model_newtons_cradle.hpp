// GENERATED FILE - DO NOT EDIT.
// Written by lrchain-derive from models/newtons_cradle.toml (FNV-1a 64 0xf44ebca9cfecb16d): the double evaluators of
// the model's dispersion relation and NLS coefficients (docs/models.md).
// Regenerate with `cmake --build build --target regenerate`.
#pragma once

#include <cmath>

#include "lrchain/model.hpp"

namespace lrchain::generated::model_newtons_cradle {

// q = the parameters p, then the named intermediates of the force laws.
inline void intermediates(const double* p, double* q) noexcept {
  q[0] = p[0];
  q[1] = p[1];
  q[2] = p[2];
  const double t0 = std::pow(p[1], p[0]);
  q[3] = p[0] * t0 / (p[1]);
  const double t1 = (p[0] * p[0]);
  q[4] = (-((1.0 / 2.0) * t1 * t0 / ((p[1] * p[1]))) + (1.0 / 2.0) * p[0] * t0 / ((p[1] * p[1])));
  q[5] = (-((1.0 / 2.0) * t1 * t0 / ((p[1] * p[1] * p[1]))) + (1.0 / 3.0) * p[0] * t0 / ((p[1] * p[1] * p[1])) + (1.0 / 6.0) * (p[0] * p[0] * p[0]) * t0 / ((p[1] * p[1] * p[1])));
}

// Coefficients of det M = 0 in ascending powers of omega^2 at D1 = 4 sin^2(theta/2), sigma = sin(theta).
inline void dispersion(double D1, double sigma, const double* q, double* w) noexcept {
  (void)sigma;
  (void)q;
  w[0] = ((q[2] * q[2]) + D1 * q[3]);
  w[1] = (-1.0);
}

// NLS coefficients at omega on a branch of det M = 0 (outputs in lrchain::ModelOutput order).
inline void nls(double D1, double sigma, double omega, const double* q, double* out) noexcept {
  (void)sigma;
  (void)q;
  out[0] = q[3] * sigma / (omega);
  const double t0 = (1.0 / omega);
  out[1] = t0;
  const double t1 = -(D1 * q[3]);
  out[2] = (1.0 / 2.0) * (t1 - (2.0 * (out[0] * out[0])) + 2.0 * q[3]) * out[1];
  out[3] = 0.0;
  const double t2 = (q[2] * q[2]);
  const double t3 = (D1 * D1);
  const double t4 = (omega * omega);
  out[4] = -((t2 - (t3 * q[3]) - (4.0 * t4) + 4.0 * D1 * q[3]));
  out[5] = 1.0;
  const double t5 = (q[4] * q[4]);
  const double t6 = (-(12.0 * t4 * q[5]) - (3.0 * t3 * q[3] * q[5]) - (8.0 * t5 * D1) + 12.0 * D1 * q[3] * q[5] + 2.0 * t3 * t5 + 3.0 * t2 * q[5]);
  out[6] = -((1.0 / 2.0) * t6 * t3 * out[1] / (out[4]));
  out[7] = 0.0;
  out[8] = (-(out[3] * out[7]) + out[6]);
  out[9] = -((1.0 / 2.0) * t6 * t3 * out[1] * out[5]);
  const double t7 = -(t2);
  out[10] = -((t4 + t7 + t1));
  out[11] = (std::abs(t7) + std::abs(-(4.0 * D1 * q[3])) + std::abs(t3 * q[3]) + std::abs(4.0 * t4));
  out[12] = std::abs(1.0);
}

// The model's description for lrchain::Model (parameters, ranges, branches, evaluators).
inline lrchain::ModelDefinition definition() {
  lrchain::ModelDefinition d;
  d.name = "newtons_cradle";
  d.description = "Newton's cradle: Hertz chain with precompression and a harmonic on-site force";
  d.file_hash = 0xf44ebca9cfecb16dull;
  d.parameters.push_back({"alpha", "(1, inf)", 1.5, true, false, false, false, 1, 0});
  d.parameters.push_back({"delta0", "(0, inf)", 0.44444444444444442, true, false, false, false, 0, 0});
  d.parameters.push_back({"w0", "(0, inf)", 1, true, false, false, false, 0, 0});
  d.intermediates.push_back("K2");
  d.intermediates.push_back("K3");
  d.intermediates.push_back("K4");
  d.branch_names.push_back("branch0");
  d.mean_flow = false;
  d.degree = 1;
  d.evaluators = {&intermediates, &dispersion, &nls};
  return d;
}

}  // namespace lrchain::generated::model_newtons_cradle
