#pragma once
// C++ text of a GiNaC expression for the lattice kernels: rationals as double quotients, small
// integer powers as products, half-integer powers as x^K sqrt(x), other powers through std::pow;
// sums and products in a canonical order; symbols print their names (array accesses x_0[i+1]).
#include <ginac/ginac.h>

#include <string>

namespace lrchain::derivation {

std::string c_expression(const GiNaC::ex& e);

}  // namespace lrchain::derivation
