#include "lrchain/regime/regime_functions.hpp"

namespace lrchain::regime {

namespace {
// h_tilde * nonresonance1 * nonresonance2 (eq:h_tilde with both poles cleared). Uses the field
// NlsCoefficients::h_tilde_numerator (smooth across the poles) when the library provides it.
template <class C>
double h_tilde_numerator_of(const C& c) {
  if constexpr (requires { c.h_tilde_numerator; }) {
    return c.h_tilde_numerator;
  } else {
    return c.h_tilde * c.nonresonance1 * c.nonresonance2;
  }
}
}  // namespace

double RegimeSample::operator[](BoundaryCause c) const {
  switch (c) {
    case BoundaryCause::curvature_zero: return curvature;
    case BoundaryCause::h_tilde_zero: return h_tilde_numerator;
    case BoundaryCause::nonresonance1: return nonresonance1;
    case BoundaryCause::nonresonance2: return nonresonance2;
    case BoundaryCause::band_edge: return 1.0;
  }
  return 1.0;
}

RegimeSample regime_sample(const NlsCoefficients& c) {
  return {c.curvature, h_tilde_numerator_of(c), c.nonresonance1, c.nonresonance2};
}

RegimeFunctions regime_functions(const Params& p, Branch b) {
  validate(p);
  const TaylorCoefficients K = taylor_coefficients(p);
  return [p, K, b](double theta) { return regime_sample(coefficients_unchecked(p, K, b, theta)); };
}

}  // namespace lrchain::regime
