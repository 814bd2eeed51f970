#pragma once
// Emission of double-precision C++ evaluators for derived expressions: numerators and
// denominators factored, common subexpressions shared as named temporaries, exact integer
// exponents printed as products (never pow()).
#include <ginac/ginac.h>

#include <map>
#include <string>
#include <utility>
#include <vector>

namespace lrchain::derivation {

struct EmittedFunction {
  std::string name;                                   // C++ function name
  std::string comment;                                // one-line doc comment
  std::vector<std::pair<GiNaC::ex, std::string>> inputs;   // symbol -> parameter name
  std::vector<std::pair<std::string, GiNaC::ex>> outputs;      // in order; later ones may use earlier names
  std::map<std::string, GiNaC::ex> output_symbols;            // output name -> symbol standing for it
  std::string result_type;                            // struct type returned
};

// C++ source for one inline function filling `result_type` (fields = output names).
std::string emit_function(const EmittedFunction& f);

// Factored canonical form used for emission: factor(numerator)/factor(denominator).
GiNaC::ex factored(const GiNaC::ex& e);

}  // namespace lrchain::derivation
