#pragma once
// The checked evaluation of a loaded model's coefficients (lrchain/coefficient_check.hpp), used by
// coefficients(), coefficients_from_evaluators(), coefficients_at() and the batch.
#include "lrchain/coefficients.hpp"
#include "lrchain/index.hpp"

namespace lrchain {

struct ModelDefinition;

namespace detail {

// The emitted evaluators at theta without any check (false: no positive omega^2 on the branch).
bool unchecked_model_coefficients(const ModelDefinition& d, const double* q, Index branch, double theta,
                                  NlsCoefficients& c) noexcept;

// c (from unchecked_model_coefficients at c.theta) checked against omega's derivatives and against
// rounding noise in h, h_tilde; else replaced by the limit of symmetric nearby evaluations; else
// refused (CoefficientEvaluation::refused, Regime::singular, NaN coefficients).
void check_or_limit(const ModelDefinition& d, const double* q, Index branch, NlsCoefficients& c) noexcept;

}  // namespace detail
}  // namespace lrchain
