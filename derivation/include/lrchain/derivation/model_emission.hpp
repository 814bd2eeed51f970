#pragma once
// C++ evaluators of a derived model file (docs/models.md): the named
// intermediates, det M in powers of omega^2, and the NLS coefficients in lrchain::ModelOutput
// order, with the signatures of lrchain::ModelEvaluators; and the headers that ship them.
#include <string>
#include <vector>

#include "lrchain/derivation/emit_cpp.hpp"
#include "lrchain/derivation/model_derivation.hpp"

namespace lrchain::derivation {

// The functions intermediates(p, q), dispersion(D1, sigma, q, w), nls(D1, sigma, omega, q, out) and
// harmonics(D1, sigma, omega, q, out) (the second-order terms per field, in long double or the nls's
// extended type).
// nls computes in `arithmetic` ("double", "long double", "__float128"; empty: evaluator_precision of
// the measured cancellation) from inputs made consistent at that precision (helpers emitted too);
// in "double", omega'' comes from implicit differentiation of det M, and points with theta < 0.05 or
// where h, h_tilde or a non-resonance value cancels by more than 1e4 go to a long double nls_extended.
std::string model_evaluator_functions(const ModelDerivation& m, const Symbols& s, const std::string& arithmetic = "");

// model_evaluator_functions (not "double") in three parts, so that nls and harmonics, the large
// ones, can be compiled as translation units of their own: `common` (intermediates, dispersion and
// their extended forms, which both call), `nls`, `harmonics`. The text is common + nls + "\n" + harmonics.
struct EvaluatorParts {
  std::string common, nls, harmonics;
};
EvaluatorParts model_evaluator_parts(const ModelDerivation& m, const Symbols& s, const std::string& arithmetic = "");

// The same four as expressions (what model_evaluator_functions prints, in double), in that order: inputs and
// outputs are named p[i], q[i], D1, sigma, omega, w[k], out[k].
std::vector<EmittedFunction> model_evaluator_definitions(const ModelDerivation& m, const Symbols& s);

// Worst cancellation sum |terms| / |sum| over the polynomial factors of the emitted NLS outputs (50
// digits), on every real branch at theta / pi = 0.001, 0.01, 0.3, 0.7, 0.99, 0.999 and the derivation's
// parameter values: the factor by which rounding errors of the evaluation are amplified.
double evaluator_cancellation(const ModelDerivation& m, const Symbols& s);

// Arithmetic type of the emitted nls() for a measured cancellation: "long double" or "__float128".
std::string evaluator_precision(double cancellation);

// definition(): the lrchain::ModelDefinition of the model (names, ranges, branches, evaluators).
std::string model_definition_function(const ModelDerivation& m);

// Text of lib/include/lrchain/generated/model_<name>.hpp.
std::string model_header(const ModelDerivation& m, const Symbols& s, const std::string& arithmetic = "");

// Text of lib/include/lrchain/generated/shipped_models.hpp (includes every model header).
std::string shipped_models_header(const std::vector<std::string>& names);

}  // namespace lrchain::derivation
