// GENERATED FILE - DO NOT EDIT.
// Written by lrchain-derive from models/resonant_chain_polynomial.toml (FNV-1a 64 0xd6c25d1014f797cc): the double evaluators of
// the model's dispersion relation and NLS coefficients (docs/models.md).
// Regenerate with `cmake --build build --target regenerate`.
#pragma once

#include <cmath>

#include "lrchain/model.hpp"

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

// NLS coefficients at omega on a branch of det M = 0 (outputs in lrchain::ModelOutput order).
inline void nls(double D1, double sigma, double omega, const double* q, double* out) noexcept {
  (void)sigma;
  (void)q;
  const double t0 = (q[3] * q[3]);
  const double t1 = (omega * omega);
  const double t2 = (omega * omega * omega * omega);
  const double t3 = (q[6] * q[6]);
  const double t4 = (-(t1 * q[6]) + q[3]);
  const double t5 = (t4 * t4);
  out[0] = t5 * q[0] * sigma / ((t0 - (2.0 * t1 * q[3] * q[6]) + t2 * t3 + t0 * q[6]) * omega);
  out[1] = t5 / ((t0 - (2.0 * t1 * q[3] * q[6]) + t2 * t3 + t0 * q[6]) * omega);
  const double t6 = (omega * omega * omega * omega * omega * omega);
  const double t7 = (q[6] * q[6] * q[6]);
  const double t8 = (out[0] * out[0]);
  const double t9 = (q[3] * q[3] * q[3]);
  out[2] = -((1.0 / 2.0) * (-(t6 * t7 * D1 * q[0]) - (2.0 * t6 * t8 * t7) - (2.0 * t9 * q[0]) - (3.0 * t1 * t0 * D1 * q[0] * q[6]) - (6.0 * t1 * t8 * t0 * q[6]) - (6.0 * t2 * t3 * q[0] * q[3]) + t9 * D1 * q[0] + 2.0 * t6 * t7 * q[0] + 2.0 * t8 * t9 + 2.0 * t8 * t9 * q[6] + 3.0 * t2 * t3 * D1 * q[0] * q[3] + 6.0 * t1 * t8 * t0 * t3 + 6.0 * t1 * t0 * q[0] * q[6] + 6.0 * t2 * t8 * t3 * q[3]) * out[1] / ((t4 * t4 * t4)));
  out[3] = -(D1 * out[1] * q[1]);
  const double t10 = (D1 * D1);
  out[4] = -((-(t10 * q[0] * q[3]) - (16.0 * t1 * D1 * q[0] * q[6]) - (4.0 * t1 * q[3]) - (4.0 * t1 * q[3] * q[6]) + 16.0 * t2 * q[6] + 4.0 * t10 * t1 * q[0] * q[6] + 4.0 * D1 * q[0] * q[3]));
  const double t11 = -(q[0]);
  const double t12 = t8 * q[6];
  out[5] = (t8 + t11 + t12);
  const double t13 = (omega * omega * omega * omega * omega * omega * omega * omega * omega * omega);
  const double t14 = (q[6] * q[6] * q[6] * q[6] * q[6]);
  const double t15 = (q[3] * q[3] * q[3] * q[3] * q[3] * q[3]);
  const double t16 = (q[6] * q[6] * q[6] * q[6]);
  const double t17 = (D1 * D1 * D1);
  const double t18 = (omega * omega * omega * omega * omega * omega * omega * omega);
  const double t19 = (q[1] * q[1]);
  const double t20 = (q[4] * q[4]);
  const double t21 = (D1 * D1 * D1 * D1);
  const double t22 = (q[3] * q[3] * q[3] * q[3] * q[3]);
  const double t23 = (q[3] * q[3] * q[3] * q[3]);
  const double t24 = (omega * omega * omega * omega * omega * omega * omega * omega * omega * omega * omega * omega);
  out[6] = -((1.0 / 2.0) * (-(12.0 * t10 * t13 * t0 * t14 * q[2]) - (12.0 * t10 * t1 * t15 * q[2]) - (12.0 * t10 * t1 * t15 * q[2] * q[6]) - (12.0 * t13 * t0 * t16 * q[5]) - (12.0 * t13 * t0 * t14 * q[5]) - (136.0 * t17 * t18 * t19 * t0 * t16) - (16.0 * t10 * t13 * t20 * t14 * q[0]) - (16.0 * t21 * t1 * t19 * t22 * q[6]) - (176.0 * t17 * t2 * t19 * t23 * t3) - (204.0 * t10 * t13 * t0 * t16 * q[2]) - (24.0 * t18 * t20 * t16 * D1 * q[0] * q[3]) - (264.0 * t10 * t6 * t23 * t3 * q[2]) - (3.0 * t10 * t18 * t0 * t16 * q[0] * q[5]) - (3.0 * t21 * t15 * q[0] * q[2]) - (336.0 * t17 * t6 * t9 * t7 * q[0] * q[2]) - (48.0 * t17 * t13 * t14 * q[0] * q[2] * q[3]) - (48.0 * t13 * t14 * D1 * q[0] * q[3] * q[5]) - (51.0 * t21 * t18 * t0 * t16 * q[0] * q[2]) - (56.0 * t21 * t6 * t19 * t9 * t7) - (64.0 * t24 * t20 * t14) - (66.0 * t21 * t2 * t23 * t3 * q[0] * q[2]) - (72.0 * t10 * t6 * t23 * t7 * q[2]) - (8.0 * t17 * t19 * t15) - (8.0 * t21 * t13 * t19 * t14 * q[3]) - (96.0 * t17 * t1 * t22 * q[0] * q[2] * q[6]) + 12.0 * t10 * t13 * t14 * q[0] * q[3] * q[5] + 12.0 * t17 * t15 * q[0] * q[2] + 12.0 * t21 * t13 * t14 * q[0] * q[2] * q[3] + 12.0 * t18 * t0 * t16 * D1 * q[0] * q[5] + 2.0 * t21 * t19 * t15 + 204.0 * t17 * t18 * t0 * t16 * q[0] * q[2] + 224.0 * t17 * t6 * t19 * t9 * t7 + 24.0 * t21 * t1 * t22 * q[0] * q[2] * q[6] + 24.0 * t13 * t20 * t16 * q[3] + 24.0 * t13 * t20 * t14 * q[3] + 264.0 * t17 * t2 * t23 * t3 * q[0] * q[2] + 32.0 * t17 * t13 * t19 * t14 * q[3] + 336.0 * t10 * t18 * t9 * t7 * q[2] + 34.0 * t21 * t18 * t19 * t0 * t16 + 44.0 * t21 * t2 * t19 * t23 * t3 + 48.0 * t10 * t24 * t14 * q[2] * q[3] + 48.0 * t10 * t2 * t22 * t3 * q[2] + 48.0 * t10 * t18 * t9 * t16 * q[2] + 48.0 * t24 * t14 * q[3] * q[5] + 6.0 * t10 * t18 * t20 * t16 * q[0] * q[3] + 64.0 * t17 * t1 * t19 * t22 * q[6] + 64.0 * t13 * t20 * t14 * D1 * q[0] + 84.0 * t21 * t6 * t9 * t7 * q[0] * q[2] + 96.0 * t10 * t2 * t22 * q[2] * q[6]) * out[1] / ((t4 * t4 * t4 * t4) * out[4] * q[3]));
  out[7] = 2.0 * D1 * q[1] / (out[5]);
  out[8] = (-(out[3] * out[7]) + out[6]);
  out[9] = -((1.0 / 2.0) * (-(12.0 * t10 * t13 * t0 * t14 * out[1] * out[5] * q[2]) - (12.0 * t10 * t1 * t15 * out[1] * out[5] * q[2]) - (12.0 * t10 * t1 * t15 * out[1] * out[5] * q[2] * q[6]) - (12.0 * t13 * t0 * t16 * out[1] * out[5] * q[5]) - (12.0 * t13 * t0 * t14 * out[1] * out[5] * q[5]) - (136.0 * t17 * t18 * t19 * t0 * t16 * out[1] * out[5]) - (16.0 * t10 * t13 * t20 * t14 * out[1] * out[5] * q[0]) - (16.0 * t21 * t1 * t19 * t22 * out[1] * out[5] * q[6]) - (16.0 * t1 * t23 * D1 * out[3] * out[4] * q[1] * q[6]) - (16.0 * t6 * t0 * t7 * D1 * out[3] * out[4] * q[1]) - (176.0 * t17 * t2 * t19 * t23 * t3 * out[1] * out[5]) - (204.0 * t10 * t13 * t0 * t16 * out[1] * out[5] * q[2]) - (24.0 * t18 * t20 * t16 * D1 * out[1] * out[5] * q[0] * q[3]) - (264.0 * t10 * t6 * t23 * t3 * out[1] * out[5] * q[2]) - (3.0 * t10 * t18 * t0 * t16 * out[1] * out[5] * q[0] * q[5]) - (3.0 * t21 * t15 * out[1] * out[5] * q[0] * q[2]) - (336.0 * t17 * t6 * t9 * t7 * out[1] * out[5] * q[0] * q[2]) - (48.0 * t17 * t13 * t14 * out[1] * out[5] * q[0] * q[2] * q[3]) - (48.0 * t13 * t14 * D1 * out[1] * out[5] * q[0] * q[3] * q[5]) - (51.0 * t21 * t18 * t0 * t16 * out[1] * out[5] * q[0] * q[2]) - (56.0 * t21 * t6 * t19 * t9 * t7 * out[1] * out[5]) - (64.0 * t24 * t20 * t14 * out[1] * out[5]) - (66.0 * t21 * t2 * t23 * t3 * out[1] * out[5] * q[0] * q[2]) - (72.0 * t10 * t6 * t23 * t7 * out[1] * out[5] * q[2]) - (8.0 * t17 * t19 * t15 * out[1] * out[5]) - (8.0 * t21 * t13 * t19 * t14 * out[1] * out[5] * q[3]) - (96.0 * t17 * t1 * t22 * out[1] * out[5] * q[0] * q[2] * q[6]) + 12.0 * t10 * t13 * t14 * out[1] * out[5] * q[0] * q[3] * q[5] + 12.0 * t17 * t15 * out[1] * out[5] * q[0] * q[2] + 12.0 * t21 * t13 * t14 * out[1] * out[5] * q[0] * q[2] * q[3] + 12.0 * t18 * t0 * t16 * D1 * out[1] * out[5] * q[0] * q[5] + 2.0 * t21 * t19 * t15 * out[1] * out[5] + 204.0 * t17 * t18 * t0 * t16 * out[1] * out[5] * q[0] * q[2] + 224.0 * t17 * t6 * t19 * t9 * t7 * out[1] * out[5] + 24.0 * t21 * t1 * t22 * out[1] * out[5] * q[0] * q[2] * q[6] + 24.0 * t13 * t20 * t16 * out[1] * out[5] * q[3] + 24.0 * t13 * t20 * t14 * out[1] * out[5] * q[3] + 24.0 * t2 * t9 * t3 * D1 * out[3] * out[4] * q[1] + 264.0 * t17 * t2 * t23 * t3 * out[1] * out[5] * q[0] * q[2] + 32.0 * t17 * t13 * t19 * t14 * out[1] * out[5] * q[3] + 336.0 * t10 * t18 * t9 * t7 * out[1] * out[5] * q[2] + 34.0 * t21 * t18 * t19 * t0 * t16 * out[1] * out[5] + 4.0 * t18 * t16 * D1 * out[3] * out[4] * q[1] * q[3] + 4.0 * t22 * D1 * out[3] * out[4] * q[1] + 44.0 * t21 * t2 * t19 * t23 * t3 * out[1] * out[5] + 48.0 * t10 * t24 * t14 * out[1] * out[5] * q[2] * q[3] + 48.0 * t10 * t2 * t22 * t3 * out[1] * out[5] * q[2] + 48.0 * t10 * t18 * t9 * t16 * out[1] * out[5] * q[2] + 48.0 * t24 * t14 * out[1] * out[5] * q[3] * q[5] + 6.0 * t10 * t18 * t20 * t16 * out[1] * out[5] * q[0] * q[3] + 64.0 * t17 * t1 * t19 * t22 * out[1] * out[5] * q[6] + 64.0 * t13 * t20 * t14 * D1 * out[1] * out[5] * q[0] + 84.0 * t21 * t6 * t9 * t7 * out[1] * out[5] * q[0] * q[2] + 96.0 * t10 * t2 * t22 * out[1] * out[5] * q[2] * q[6]) / ((t4 * t4 * t4 * t4) * q[3]));
  out[10] = (-(t1 * D1 * q[0] * q[6]) - (t1 * q[3]) - (t1 * q[3] * q[6]) + t2 * q[6] + D1 * q[0] * q[3]);
  out[11] = (std::abs(-(16.0 * t2 * q[6])) + std::abs(-(4.0 * t10 * t1 * q[0] * q[6])) + std::abs(-(4.0 * D1 * q[0] * q[3])) + std::abs(t10 * q[0] * q[3]) + std::abs(16.0 * t1 * D1 * q[0] * q[6]) + std::abs(4.0 * t1 * q[3]) + std::abs(4.0 * t1 * q[3] * q[6]));
  out[12] = (std::abs(t8) + std::abs(t11) + std::abs(t12));
}

// The model's description for lrchain::Model (parameters, ranges, branches, evaluators).
inline lrchain::ModelDefinition definition() {
  lrchain::ModelDefinition d;
  d.name = "resonant_chain_polynomial";
  d.description = "locally resonant chain with polynomial bond forces and nonlinear resonators";
  d.file_hash = 0xd6c25d1014f797ccull;
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
  d.evaluators = {&intermediates, &dispersion, &nls};
  return d;
}

}  // namespace lrchain::generated::model_resonant_chain_polynomial
