#pragma once
// The derivation pipeline as used by lrchain-derive and the tests: both models derived,
// checks run, and the generated header text produced.
#include <string>
#include <vector>

#include "lrchain/derivation/multiscale.hpp"
#include "lrchain/derivation/paper_checks.hpp"

namespace lrchain::derivation {

struct Derivation {
  Symbols symbols;
  LatticeDescription resonant, homogeneous;
  DerivedCoefficients resonant_coefficients, homogeneous_coefficients;
};

// Derives both models (eq:Hertz with and without resonators).
Derivation derive_all();

// Text of lib/include/lrchain/generated/nls_coefficients.hpp.
std::string generated_header(const Derivation& d);

// The human-readable derivation report (orders, coefficients, checks).
std::string report(const Derivation& d, const std::vector<CheckResult>& checks);

}  // namespace lrchain::derivation
