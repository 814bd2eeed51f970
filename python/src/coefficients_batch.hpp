#pragma once
// The resonant chain's NLS coefficients over a contiguous array of wavenumbers into columns
// (structure of arrays), in one vectorised loop (coefficients_batch.cpp).
#include <cstddef>
#include <cstdint>

#include "lrchain/coefficients.hpp"

namespace lrchain::python {

// Output columns, each of n values: the fields in kCoefficientFields order (coefficient_arrays.hpp)
// and the Regime codes.
struct CoefficientColumns {
  double* field[10];
  std::int8_t* regime;
};

// Coefficients at theta[0..n) (each in (-pi, pi], nonzero on the acoustic branch; p valid) into
// out; bit-identical to coefficients_unchecked. Allocation-free, no Python calls.
void evaluate_resonant_chain(const Params& p, Branch b, const double* theta, std::ptrdiff_t n,
                             const CoefficientColumns& out);

}  // namespace lrchain::python
