#pragma once
// Small symbolic linear algebra for the order-by-order solve (n = number of fields).
#include <ginac/ginac.h>

#include <vector>

namespace lrchain::derivation {

// Right (or left) null vector of a singular n x n matrix, from a column (row) of the adjugate,
// scaled so that its first entry is 1. Picks the simplest admissible column/row.
std::vector<GiNaC::ex> null_vector(const GiNaC::matrix& L, bool right);

// A solution p of L p = rhs with p[0] = 0 (rhs in the range of L): rows 1..n-1 of the system
// restricted to the unknowns 1..n-1 (the first field's amplitude stays free).
std::vector<GiNaC::ex> particular_solution(const GiNaC::matrix& L, const std::vector<GiNaC::ex>& rhs);

}  // namespace lrchain::derivation
