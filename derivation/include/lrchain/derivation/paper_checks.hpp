#pragma once
// Checks of the derived coefficients against the paper's printed formulas (used only as checks),
// implicit differentiation of det M = 0, the theta = pi / theta = 0 edge values, and the
// rho -> 0 limit against the homogeneous chain (Chong13).
#include <string>
#include <vector>

#include "lrchain/derivation/multiscale.hpp"

namespace lrchain::derivation {

struct CheckResult {
  std::string name;    // what is compared
  bool passed = false;
  std::string method;  // "symbolic" (normal() of the difference is 0) or "numeric, N points"
  std::string detail;  // e.g. the max relative difference
};

std::vector<CheckResult> run_paper_checks(const DerivedCoefficients& resonant,
                                          const DerivedCoefficients& homogeneous, const Symbols& s);

}  // namespace lrchain::derivation
