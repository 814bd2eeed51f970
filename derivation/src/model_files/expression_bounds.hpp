#pragma once
// Bounds on what an expression of a model file may ask of the symbolic engine, checked on its text
// before GiNaC reads it: GiNaC evaluates powers of numbers exactly at once (10^10000000 takes
// minutes and gigabytes), expands powers of fields, and exp of a huge number overflows later.
#include <string>

namespace lrchain::derivation {

inline constexpr double kMaxNumberDigits = 2000;  // exact numbers up to ~10^2000
inline constexpr double kMaxPolynomialDegree = 12;  // forces are used to cubic order
inline constexpr double kMaxExponentialArgument = 700;  // exp(700) ~ 1e304, near the double limit
inline constexpr long kMaxNestingDepth = 64;  // parentheses inside parentheses

// "" when `plain` (a translated expression: numbers, names, + - * / ^, parentheses, calls) stays
// within the bounds, else the sentence that says which bound it breaks.
std::string expression_bound_problem(const std::string& plain);

}  // namespace lrchain::derivation
