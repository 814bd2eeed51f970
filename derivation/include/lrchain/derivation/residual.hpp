#pragma once
// Substitution of the multiple-scale ansatz (eq:ansatz) into a lattice model: the residual
// inertia*d^2 field/dt^2 - rhs collected by powers eps^k E^j, k <= 3 (Appendix A).
#include <ginac/ginac.h>

#include <map>
#include <vector>

#include "lrchain/derivation/jets.hpp"
#include "lrchain/derivation/model.hpp"

namespace lrchain::derivation {

inline constexpr int kMaxOrder = 3;

// residual[f][k][j + kMaxOrder]: coefficient of eps^k E^j in equation f (k = 0..3, |j| <= 3).
using Residual = std::vector<std::vector<std::vector<GiNaC::ex>>>;

// Reduces sin^2(theta) = D1 - D1^2/4 (sigma = sin theta, D1 = 2(1 - cos theta)) and expands.
GiNaC::ex reduce_trig(const GiNaC::ex& e, const Symbols& s);

Residual build_residual(const LatticeDescription& model, const Symbols& s, Jets& jets);

}  // namespace lrchain::derivation
