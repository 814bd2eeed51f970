// GENERATED FILE - DO NOT EDIT.
// Written by lrchain-derive from models/diatomic_chain.toml (FNV-1a 64 0xe672bce94294c28b): the double evaluators of
// the model's dispersion relation and NLS coefficients (docs/models.md).
// Regenerate with `cmake --build build --target regenerate`.
#pragma once

#include <cmath>

#include "lrchain/model.hpp"

namespace lrchain::generated::model_diatomic_chain {

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
  w[0] = -(((D1 * D1) - (8.0 * D1) + 4.0 * (sigma * sigma)) * (q[3] * q[3]));
  w[1] = 8.0 * ((-1.0) - (q[2])) * q[3];
  w[2] = 4.0 * q[2];
}

// NLS coefficients at omega on a branch of det M = 0 (outputs in lrchain::ModelOutput order).
inline void nls(double D1, double sigma, double omega, const double* q, double* out) noexcept {
  (void)sigma;
  (void)q;
  const double t0 = (D1 * D1);
  const double t1 = (q[3] * q[3]);
  const double t2 = -(t0 * t1);
  const double t3 = (omega * omega * omega * omega);
  const double t4 = (sigma * sigma);
  const double t5 = -(4.0 * t1 * t4);
  const double t6 = (omega * omega);
  const double t7 = 8.0 * t1 * D1;
  out[0] = 4.0 * (t6 - (2.0 * q[3])) * t1 * sigma / ((t2 - (16.0 * t1) - (16.0 * t1 * q[2]) - (4.0 * t3 * q[2]) + t5 + 16.0 * t6 * q[2] * q[3] + t7) * omega);
  const double t8 = t1 * D1;
  const double t9 = (-(D1) + 4.0);
  out[1] = -(t9 * t1 / ((-(t3 * q[2]) - (4.0 * t1) - (4.0 * t1 * q[2]) + t8 + 4.0 * t6 * q[2] * q[3]) * omega));
  const double t10 = (out[0] * out[0]);
  const double t11 = (q[3] * q[3] * q[3]);
  const double t12 = (q[3] * q[3] * q[3] * q[3]);
  const double t13 = (q[2] * q[2]);
  const double t14 = (omega * omega * omega * omega * omega * omega);
  out[2] = (1.0 / 2.0) * (-(t3 * t1 * D1 * q[2]) - (16.0 * t10 * t11) - (16.0 * t10 * t11 * q[2]) - (2.0 * t6 * t10 * t1 * D1 * q[2]) - (2.0 * t12 * D1) - (24.0 * t6 * t10 * t13 * t1) - (4.0 * t3 * t10 * q[2] * q[3]) - (6.0 * t14 * t10 * t13) - (8.0 * t6 * t11) - (8.0 * t6 * t11 * q[2]) - (8.0 * (omega * omega * omega) * t1 * out[0] * q[2] * sigma) + 16.0 * t11 * omega * out[0] * q[2] * sigma + 2.0 * t6 * t11 * D1 + 2.0 * t6 * t11 * D1 * q[2] + 24.0 * t6 * t10 * t1 * q[2] + 24.0 * t3 * t10 * t13 * q[3] + 4.0 * t3 * t1 * q[2] + 4.0 * t10 * t11 * D1 + 8.0 * t12) * out[1] / ((-(t6 * q[2]) + 2.0 * q[3]) * t9 * (q[3] * q[3]));
  const double t15 = (t3 - (t6 * D1 * q[3]) + t8);
  out[3] = -(t15 * out[1] * q[4] / (t9 * (q[3] * q[3])));
  const double t16 = (D1 * D1 * D1 * D1);
  const double t17 = (D1 * D1 * D1);
  out[4] = -((1.0 / 4.0) * (-(t16 * t1) - (16.0 * t1 * t4) - (24.0 * t0 * t1) - (32.0 * t6 * q[2] * q[3]) - (32.0 * t6 * q[3]) - (4.0 * t0 * t1 * t4) + 16.0 * t1 * t4 * D1 + 32.0 * t1 * D1 + 64.0 * t3 * q[2] + 8.0 * t17 * t1));
  const double t18 = -(q[3]);
  const double t19 = 2.0 * t10;
  const double t20 = 2.0 * t10 * q[2];
  out[5] = (1.0 / 2.0) * (t18 + t19 + t20);
  const double t21 = (q[4] * q[4]);
  const double t22 = (q[3] * q[3] * q[3] * q[3] * q[3] * q[3]);
  const double t23 = (omega * omega * omega * omega * omega * omega * omega * omega);
  const double t24 = (omega * omega * omega * omega * omega * omega * omega * omega * omega * omega);
  const double t25 = (q[3] * q[3] * q[3] * q[3] * q[3]);
  const double t26 = (omega * omega * omega * omega * omega * omega * omega * omega * omega * omega * omega * omega);
  out[6] = (-(12.0 * t17 * t3 * t11 * t21) - (12.0 * t17 * t22 * q[5]) - (144.0 * t23 * t1 * D1 * q[2] * q[5]) - (16.0 * t0 * t23 * t21 * q[2] * q[3]) - (16.0 * t24 * t21 * D1 * q[2]) - (2.0 * t0 * t23 * t21 * q[3]) - (2.0 * t16 * t3 * t11 * t21) - (2.0 * t16 * t25 * t21) - (32.0 * t17 * t6 * t12 * t21) - (48.0 * t0 * t23 * t1 * q[2] * q[5]) - (48.0 * t26 * q[2] * q[5]) - (6.0 * t17 * t3 * t12 * q[5]) - (6.0 * t17 * t14 * t11 * q[5]) - (6.0 * t16 * t6 * t25 * q[5]) - (60.0 * t23 * t1 * D1 * q[5]) - (64.0 * t14 * t1 * t21 * D1) - (64.0 * t14 * t1 * t21 * D1 * q[2]) - (72.0 * t0 * t3 * t12 * q[5]) - (96.0 * t0 * t3 * t12 * q[2] * q[5]) + 120.0 * t0 * t14 * t11 * q[2] * q[5] + 16.0 * t0 * t14 * t1 * t21 * q[2] + 24.0 * t0 * t6 * t25 * q[2] * q[5] + 24.0 * t0 * t6 * t25 * q[5] + 24.0 * t17 * t6 * t25 * q[5] + 24.0 * t24 * q[2] * q[3] * q[5] + 24.0 * t24 * q[3] * q[5] + 3.0 * t0 * t23 * t1 * q[5] + 3.0 * t16 * t3 * t12 * q[5] + 3.0 * t16 * t22 * q[5] + 4.0 * t0 * t24 * t21 * q[2] + 4.0 * t17 * t14 * t1 * t21 + 48.0 * t0 * t14 * t11 * q[5] + 48.0 * t14 * t11 * D1 * q[2] * q[5] + 48.0 * t14 * t11 * D1 * q[5] + 64.0 * t23 * t21 * D1 * q[2] * q[3] + 8.0 * t17 * t25 * t21 + 8.0 * t16 * t6 * t12 * t21 + 8.0 * t23 * t21 * D1 * q[3] + 80.0 * t0 * t3 * t11 * t21 + 96.0 * t24 * D1 * q[2] * q[3] * q[5]) * out[1] / ((t9 * t9) * out[4] * (q[3] * q[3] * q[3] * q[3]));
  out[7] = 2.0 * t15 * q[4] / (t9 * out[5] * (q[3] * q[3]));
  out[8] = (-(out[3] * out[7]) + out[6]);
  out[9] = (-(12.0 * t17 * t3 * t11 * t21 * out[1] * out[5]) - (12.0 * t17 * t22 * out[1] * out[5] * q[5]) - (144.0 * t23 * t1 * D1 * out[1] * out[5] * q[2] * q[5]) - (16.0 * t0 * t23 * t21 * out[1] * out[5] * q[2] * q[3]) - (16.0 * t24 * t21 * D1 * out[1] * out[5] * q[2]) - (2.0 * t0 * t6 * t11 * out[3] * out[4] * q[4]) - (2.0 * t0 * t23 * t21 * out[1] * out[5] * q[3]) - (2.0 * t16 * t3 * t11 * t21 * out[1] * out[5]) - (2.0 * t16 * t25 * t21 * out[1] * out[5]) - (32.0 * t17 * t6 * t12 * t21 * out[1] * out[5]) - (48.0 * t0 * t23 * t1 * out[1] * out[5] * q[2] * q[5]) - (48.0 * t26 * out[1] * out[5] * q[2] * q[5]) - (6.0 * t17 * t3 * t12 * out[1] * out[5] * q[5]) - (6.0 * t17 * t14 * t11 * out[1] * out[5] * q[5]) - (6.0 * t16 * t6 * t25 * out[1] * out[5] * q[5]) - (60.0 * t23 * t1 * D1 * out[1] * out[5] * q[5]) - (64.0 * t14 * t1 * t21 * D1 * out[1] * out[5]) - (64.0 * t14 * t1 * t21 * D1 * out[1] * out[5] * q[2]) - (72.0 * t0 * t3 * t12 * out[1] * out[5] * q[5]) - (8.0 * t3 * t1 * out[3] * out[4] * q[4]) - (8.0 * t12 * D1 * out[3] * out[4] * q[4]) - (96.0 * t0 * t3 * t12 * out[1] * out[5] * q[2] * q[5]) + 120.0 * t0 * t14 * t11 * out[1] * out[5] * q[2] * q[5] + 16.0 * t0 * t14 * t1 * t21 * out[1] * out[5] * q[2] + 2.0 * t0 * t12 * out[3] * out[4] * q[4] + 2.0 * t3 * t1 * D1 * out[3] * out[4] * q[4] + 24.0 * t0 * t6 * t25 * out[1] * out[5] * q[2] * q[5] + 24.0 * t0 * t6 * t25 * out[1] * out[5] * q[5] + 24.0 * t17 * t6 * t25 * out[1] * out[5] * q[5] + 24.0 * t24 * out[1] * out[5] * q[2] * q[3] * q[5] + 24.0 * t24 * out[1] * out[5] * q[3] * q[5] + 3.0 * t0 * t23 * t1 * out[1] * out[5] * q[5] + 3.0 * t16 * t3 * t12 * out[1] * out[5] * q[5] + 3.0 * t16 * t22 * out[1] * out[5] * q[5] + 4.0 * t0 * t24 * t21 * out[1] * out[5] * q[2] + 4.0 * t17 * t14 * t1 * t21 * out[1] * out[5] + 48.0 * t0 * t14 * t11 * out[1] * out[5] * q[5] + 48.0 * t14 * t11 * D1 * out[1] * out[5] * q[2] * q[5] + 48.0 * t14 * t11 * D1 * out[1] * out[5] * q[5] + 64.0 * t23 * t21 * D1 * out[1] * out[5] * q[2] * q[3] + 8.0 * t17 * t25 * t21 * out[1] * out[5] + 8.0 * t16 * t6 * t12 * t21 * out[1] * out[5] + 8.0 * t6 * t11 * D1 * out[3] * out[4] * q[4] + 8.0 * t23 * t21 * D1 * out[1] * out[5] * q[3] + 80.0 * t0 * t3 * t11 * t21 * out[1] * out[5] + 96.0 * t24 * D1 * out[1] * out[5] * q[2] * q[3] * q[5]) / ((t9 * t9) * (q[3] * q[3] * q[3] * q[3]));
  out[10] = (1.0 / 4.0) * (t2 + t5 - (8.0 * t6 * q[2] * q[3]) - (8.0 * t6 * q[3]) + 4.0 * t3 * q[2] + t7);
  out[11] = (std::abs(-(16.0 * t1 * t4 * D1)) + std::abs(-(32.0 * t1 * D1)) + std::abs(-(64.0 * t3 * q[2])) + std::abs(-(8.0 * t17 * t1)) + std::abs(t16 * t1) + std::abs(16.0 * t1 * t4) + std::abs(24.0 * t0 * t1) + std::abs(32.0 * t6 * q[2] * q[3]) + std::abs(32.0 * t6 * q[3]) + std::abs(4.0 * t0 * t1 * t4)) / (std::abs(4.0));
  out[12] = (std::abs(t18) + std::abs(t19) + std::abs(t20)) / (std::abs(2.0));
}

// The model's description for lrchain::Model (parameters, ranges, branches, evaluators).
inline lrchain::ModelDefinition definition() {
  lrchain::ModelDefinition d;
  d.name = "diatomic_chain";
  d.description = "diatomic granular chain with precompression (alternating masses 1 and m)";
  d.file_hash = 0xe672bce94294c28bull;
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
  d.evaluators = {&intermediates, &dispersion, &nls};
  return d;
}

}  // namespace lrchain::generated::model_diatomic_chain
