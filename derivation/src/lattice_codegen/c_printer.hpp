#pragma once
// C++ text of a GiNaC expression for the lattice kernels: rationals as double quotients, integer
// powers through ipow<N>, half-integer powers through half_pow<K> (x^K sqrt(x)), other powers
// through std::pow; symbols print their names (array accesses such as x_0[i+1]).
#include <ginac/ginac.h>

#include <string>

namespace lrchain::derivation {

std::string c_expression(const GiNaC::ex& e);

}  // namespace lrchain::derivation
