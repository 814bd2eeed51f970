#pragma once
// Emission of double-precision C++ evaluators for derived expressions: numerators and
// denominators factored, common subexpressions shared as named temporaries, exact integer
// exponents printed as products (never pow()). The text depends only on the expressions: operands
// of sums and products are printed in the order of their canonical text, never GiNaC's.
#include <ginac/ginac.h>

#include <map>
#include <set>
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
  std::string result_type;                            // struct type returned; empty: void function
                                                      // writing the outputs to the lvalues named
  std::string parameter_list;                         // C++ parameters; empty: double per input
  std::string prologue;                               // statements before the outputs
  std::set<std::string> unfactored;                   // outputs printed expanded (no normal/factor)
  std::set<std::string> term_scales;                  // outputs printed as sum |terms| / |denominator|
  std::string real_type = "double";                   // arithmetic type of temporaries and fractions
                                                      // (else the function defines `using real = ...`)
  std::string local_outputs;                          // non-empty: outputs out[k] are held in this local
                                                      // array (declared in the prologue) instead
  std::string abs_function = "std::abs";              // absolute value used by term_scales
  std::string epilogue;                               // statements after the outputs
};

// C++ source for one inline function filling `result_type` (fields = output names).
std::string emit_function(const EmittedFunction& f);

// Number of nodes of the emitted form of e, factor(numerator)/factor(denominator) with operands in
// canonical order (a measure of its size, independent of GiNaC's internal term order).
std::size_t emitted_size(const GiNaC::ex& e);

}  // namespace lrchain::derivation
