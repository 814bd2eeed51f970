#pragma once
// Model-file expressions: shifted fields u[n+m] and calls of the file's named functions are
// recognised, every other name must be a known symbol, then GiNaC's parser reads the text.
#include <ginac/ginac.h>

#include "expression_bounds.hpp"

#include <map>
#include <string>
#include <vector>

namespace lrchain::derivation {

struct ExpressionContext {
  std::string where;                   // "file:line: force of field u" (prefix of every message)
  GiNaC::symtab symbols;               // names allowed as plain symbols
  std::vector<std::string> fields;     // fields allowed as u[n+m] (empty: none)
  std::vector<std::vector<GiNaC::ex>> shifted;  // shifted[f][m+3]
  std::vector<std::string> functions;  // the file's named functions (callable with one argument)
  std::map<std::string, double> function_terms;  // terms of each named law's Taylor coefficients (1 if absent)
  double max_terms = kMaxExpandedTerms;  // expanded terms allowed (kMaxLawTerms for a law)
};

// One call F(arg) found in an expression: stands as `placeholder` in the parsed result.
struct FunctionCall {
  std::string function;
  GiNaC::ex argument;
  GiNaC::realsymbol placeholder;
};

// Parses `text`; throws lrchain::InputError on an undefined symbol or function, an unknown field,
// a bad index or a shift beyond +-3, a syntax error, or an expression beyond the bounds of
// expression_bounds.hpp; `expanded_terms` (if given) receives the bound on its expanded terms.
GiNaC::ex parse_model_expression(const std::string& text, const ExpressionContext& context,
                                 std::vector<FunctionCall>& calls, double* expanded_terms = nullptr);

// An expression as GiNaC prints it (plain text).
std::string to_text(const GiNaC::ex& e);

// A number "0.25", "1e-3" or fraction "4/9" read exactly (doubles as the exact binary value).
bool parse_exact_number(const std::string& text, GiNaC::numeric& value);

}  // namespace lrchain::derivation
