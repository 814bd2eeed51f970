// GENERATED FILE - DO NOT EDIT.
// Written by lrchain-derive from models/fput.toml (FNV-1a 64 0x5b104df96318551e): the double evaluators of
// the model's dispersion relation and NLS coefficients (docs/models.md).
// Regenerate with `cmake --build build --target regenerate`.
#pragma once

#include <cmath>

#include "lrchain/model.hpp"

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

// NLS coefficients at omega on a branch of det M = 0 (outputs in lrchain::ModelOutput order).
inline void nls(double D1, double sigma, double omega, const double* q, double* out) noexcept {
  (void)sigma;
  (void)q;
  out[0] = sigma / (omega);
  const double t0 = (1.0 / omega);
  out[1] = t0;
  const double t1 = -(D1);
  const double t2 = (out[0] * out[0]);
  out[2] = (1.0 / 2.0) * (t1 - (2.0 * t2) + 2.0) * out[1];
  out[3] = -(D1 * out[1] * q[0]);
  const double t3 = (D1 * D1);
  const double t4 = -(4.0 * D1);
  const double t5 = (omega * omega);
  const double t6 = 4.0 * t5;
  out[4] = (t3 + t4 + t6);
  const double t7 = -(out[0]);
  out[5] = (t7 + 1.0) * ((-1.0) + t7);
  const double t8 = (q[0] * q[0]);
  out[6] = -((1.0 / 2.0) * (-(12.0 * t5 * q[1]) - (3.0 * t3 * q[1]) - (8.0 * t8 * D1) + 12.0 * D1 * q[1] + 2.0 * t3 * t8) * t3 * out[1] / (out[4]));
  out[7] = 2.0 * D1 * q[0] / (out[5]);
  out[8] = (-(out[3] * out[7]) + out[6]);
  const double t9 = (D1 * D1 * D1);
  out[9] = (1.0 / 2.0) * (-(12.0 * t3 * out[1] * out[5] * q[1]) - (2.0 * t9 * t8 * out[1] * out[5]) - (4.0 * out[3] * out[4] * q[0]) + 12.0 * t5 * D1 * out[1] * out[5] * q[1] + 3.0 * t9 * out[1] * out[5] * q[1] + 8.0 * t3 * t8 * out[1] * out[5]) * D1;
  out[10] = -((t5 + t1));
  out[11] = (std::abs(t3) + std::abs(t4) + std::abs(t6));
  out[12] = (std::abs(t2) + std::abs((-1.0)));
}

// The model's description for lrchain::Model (parameters, ranges, branches, evaluators).
inline lrchain::ModelDefinition definition() {
  lrchain::ModelDefinition d;
  d.name = "fput";
  d.description = "Fermi-Pasta-Ulam-Tsingou chain, F(r) = r + a r^2 + b r^3";
  d.file_hash = 0x5b104df96318551eull;
  d.parameters.push_back({"a", "(-inf, inf)", 0.25, false, false, false, false, 0, 0});
  d.parameters.push_back({"b", "(-inf, inf)", 0.5, false, false, false, false, 0, 0});
  d.branch_names.push_back("acoustic");
  d.mean_flow = true;
  d.degree = 1;
  d.evaluators = {&intermediates, &dispersion, &nls};
  return d;
}

}  // namespace lrchain::generated::model_fput
