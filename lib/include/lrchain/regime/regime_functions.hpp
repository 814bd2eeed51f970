#pragma once
// The smooth functions of theta whose sign changes decide sign(omega'' h_tilde) (Sec. 3.3):
// curvature omega'' (eq:ppOmega), the numerator of h_tilde (eq:h_tilde times both non-resonance
// factors, smooth across the poles), nonresonance1 (eq:nonresonance1), nonresonance2
// (eq:nonresonance2). Focusing iff curvature * numerator * nonresonance1 * nonresonance2 < 0.
#include <functional>

#include "lrchain/coefficients.hpp"
#include "lrchain/dispersion.hpp"
#include "lrchain/params.hpp"
#include "lrchain/regime/boundary_cause.hpp"

namespace lrchain::regime {

struct RegimeSample {
  double curvature = 0;          // omega''
  double h_tilde_numerator = 0;  // h_tilde * nonresonance1 * nonresonance2
  double nonresonance1 = 0;
  double nonresonance2 = 0;

  // Value of the smooth function belonging to a cause (band_edge has none: returns 1).
  double operator[](BoundaryCause c) const;
  // sign(omega'' h_tilde) < 0 from the signs of the four smooth factors.
  bool focusing() const {
    return curvature * h_tilde_numerator * nonresonance1 * nonresonance2 < 0.0;
  }
};

// The four functions from one coefficient evaluation.
RegimeSample regime_sample(const NlsCoefficients& c);

// theta -> RegimeSample; any model (or an analytic test function) can stand behind it.
using RegimeFunctions = std::function<RegimeSample(double theta)>;

// The functions of the resonant chain for fixed parameters and branch (validates p).
RegimeFunctions regime_functions(const Params& p, Branch b);

}  // namespace lrchain::regime
