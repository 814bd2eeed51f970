#pragma once
// The checked evaluation of a loaded model's coefficients (lrchain/coefficient_check.hpp): the full
// check in coefficients() and coefficients_from_evaluators() (coeffs, ring, bright, dark), the
// derivative check with the full check as its fallback in coefficients_at() (regime maps, scans, the batch).
#include "lrchain/coefficient_check.hpp"
#include "lrchain/coefficients.hpp"
#include "lrchain/index.hpp"
#include "lrchain/model.hpp"

namespace lrchain {

struct ModelDefinition;

namespace detail {

// det M's coefficients in omega^2 at theta (ascending) and sin, cos of theta / 2: what the
// evaluation at theta computed, reused by the hot path's check.
struct DetMAtTheta {
  double sin_half, cos_half;
  double w[kMaxModelDegree + 1];
};

// implicit_derivatives (lrchain/coefficient_check.hpp) from det M at theta as computed already.
bool implicit_derivatives(const ModelDefinition& d, const double* q, const DetMAtTheta& at, double omega,
                          BranchDerivatives& out) noexcept;

// c, omega'', gamma, beta, the non-resonance values and h_tilde_numerator from the emitted NLS
// evaluator's outputs (ModelOutput order); h, lambda, h_tilde are left to the caller.
inline void store_linear_outputs(const double* out, NlsCoefficients& c) noexcept {
  c.group_velocity = out[out_group_velocity];
  c.curvature = out[out_curvature];
  c.gamma = out[out_gamma];
  c.beta = out[out_beta];
  c.nonresonance1 = out[out_nonresonance1];
  c.nonresonance2 = out[out_nonresonance2];
  c.h_tilde_numerator = out[out_h_tilde_numerator];
}

// The emitted evaluators at theta without any check (false: no positive omega^2 on the branch).
bool unchecked_model_coefficients(const ModelDefinition& d, const double* q, Index branch, double theta,
                                  NlsCoefficients& c) noexcept;

// c (from unchecked_model_coefficients at c.theta) checked against omega's derivatives and against
// rounding noise in h, h_tilde; else replaced by the limit of symmetric nearby evaluations; else
// refused (CoefficientEvaluation::refused, Regime::singular, NaN coefficients).
void check_or_limit(const ModelDefinition& d, const double* q, Index branch, NlsCoefficients& c) noexcept;

// True when every coefficient of c (unchecked, at c.theta) changes by less than 1e-6 relative over a
// step of 1e-8 in theta (one more evaluation of the emitted expressions, at omega + c 1e-8): no digits
// lost to a 0/0 of the expressions. Not a check of c and omega'' against det M.
bool screen_passes(const ModelDefinition& d, const double* q, const NlsCoefficients& c) noexcept;

// True when c's h_tilde equals its h_tilde_numerator / (nonresonance1 nonresonance2) to 1e-10 of
// |h| + |lambda beta| + |h_tilde| (or the regime is singular): the two emitted forms round
// independently, so digits lost to a 0/0 of h's expressions show as their disagreement.
bool h_tilde_consistent(const NlsCoefficients& c) noexcept;

// The hot path's check (regime maps, scans, the batch): h_tilde two ways (h_tilde_consistent), c and
// omega'' against det M's implicit derivatives (implicit_derivatives), and check_or_limit where
// either fails.
void derivatives_or_check(const ModelDefinition& d, const double* q, Index branch, const DetMAtTheta& at,
                          NlsCoefficients& c) noexcept;

}  // namespace detail
}  // namespace lrchain
