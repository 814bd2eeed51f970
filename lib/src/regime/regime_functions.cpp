#include "lrchain/regime/regime_functions.hpp"

namespace lrchain::regime {

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
  // h_tilde_numerator = h_tilde * nonresonance1 * nonresonance2, smooth across the poles.
  return {c.curvature, c.h_tilde_numerator, c.nonresonance1, c.nonresonance2};
}

RegimeFunctions regime_functions(const Params& p, Branch b) {
  validate(p);
  const TaylorCoefficients K = taylor_coefficients(p);
  return [p, K, b](double theta) { return regime_sample(coefficients_unchecked(p, K, b, theta)); };
}

}  // namespace lrchain::regime
