#pragma once
// Double-precision C++ evaluators of a derived model file (docs/models.md): the named
// intermediates, det M in powers of omega^2, and the NLS coefficients in lrchain::ModelOutput
// order, with the signatures of lrchain::ModelEvaluators; and the headers that ship them.
#include <string>
#include <vector>

#include "lrchain/derivation/emit_cpp.hpp"
#include "lrchain/derivation/model_derivation.hpp"

namespace lrchain::derivation {

// The three functions intermediates(p, q), dispersion(D1, sigma, q, w), nls(D1, sigma, omega, q, out).
std::string model_evaluator_functions(const ModelDerivation& m, const Symbols& s);

// The same three as expressions (what model_evaluator_functions prints), in that order: inputs and
// outputs are named p[i], q[i], D1, sigma, omega, w[k], out[k].
std::vector<EmittedFunction> model_evaluator_definitions(const ModelDerivation& m, const Symbols& s);

// definition(): the lrchain::ModelDefinition of the model (names, ranges, branches, evaluators).
std::string model_definition_function(const ModelDerivation& m);

// Text of lib/include/lrchain/generated/model_<name>.hpp.
std::string model_header(const ModelDerivation& m, const Symbols& s);

// Text of lib/include/lrchain/generated/shipped_models.hpp (includes every model header).
std::string shipped_models_header(const std::vector<std::string>& names);

}  // namespace lrchain::derivation
