#pragma once
// Bounds on what an expression of a model file may ask of the symbolic engine, checked on its text
// before GiNaC reads it: GiNaC evaluates powers of numbers exactly at once (10^10000000 takes
// minutes and gigabytes), expands powers of fields, and exp of a huge number overflows later.
#include <map>
#include <string>

namespace lrchain::derivation {

inline constexpr double kMaxNumberDigits = 2000;  // exact numbers up to ~10^2000
inline constexpr double kMaxPolynomialDegree = 12;  // forces are used to cubic order
inline constexpr double kMaxExponentialArgument = 700;  // exp(700) ~ 1e304, near the double limit
inline constexpr long kMaxNestingDepth = 64;  // parentheses inside parentheses
// Terms of the fully expanded expression (in parameters, fields and arguments): the derivation's
// cost grows faster than linearly with it. A force (a call counting its law's terms) up to 256;
// a function's law up to 64, as its Taylor coefficients multiply each other in h (the law
// r exp(-a r) (1+a+D)^k derives in 2.9 s with 45 terms, 5.2 s with 66, 25 s with 120).
inline constexpr double kMaxExpandedTerms = 256;
inline constexpr double kMaxLawTerms = 64;

// What the bound check learns of an expression: the sentence that says which bound it breaks ("" if
// none) and an upper bound on its number of terms once expanded.
struct ExpressionCost {
  std::string problem;
  double expanded_terms = 1;
};

// The cost of `plain` (a translated expression: numbers, names, + - * / ^, parentheses, calls);
// `symbol_terms` gives the expanded terms a placeholder name stands for (a call of a named law);
// more than `max_terms` expanded terms is a problem.
ExpressionCost expression_cost(const std::string& plain, const std::map<std::string, double>& symbol_terms = {},
                               double max_terms = kMaxExpandedTerms);

}  // namespace lrchain::derivation
