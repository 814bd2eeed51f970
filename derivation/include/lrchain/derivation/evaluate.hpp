#pragma once
// High-precision (CLN, default 50 digits) evaluation of derived expressions at a parameter point,
// independent of the numeric library: omega is the root of the derived dispersion relation.
#include <ginac/ginac.h>

#include "lrchain/derivation/multiscale.hpp"

namespace lrchain::derivation {

struct PointInput {
  double alpha, delta0, kappa, rho, theta;
  bool optical;  // optical (larger omega^2 root) or acoustic (smaller)
};

class PrecisePoint {
 public:
  // Computes K2, K3, K4 (expv), D1, sigma and omega at `digits` significant digits.
  PrecisePoint(const DerivedCoefficients& d, const Symbols& s, const PointInput& in, int digits = 50);
  // Value of an expression in D1, sigma, omega, c, gamma and the model parameters.
  GiNaC::numeric value(const GiNaC::ex& e) const;
  const GiNaC::exmap& substitutions() const { return subs_; }

 private:
  GiNaC::exmap subs_;
};

// Exact rational equal to a double (no rounding in the conversion).
GiNaC::numeric exact(double x);

}  // namespace lrchain::derivation
