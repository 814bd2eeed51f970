#pragma once
// Model parameters of the locally resonant granular chain (Sec. 2, eq:Hertz, eq:Vr).
#include <string>

namespace lrchain {

// Dimensionless parameters: Hertz exponent alpha > 1, precompression overlap delta0 > 0,
// resonator spring kappa > 0, mass ratio rho = m2/m1 > 0.
struct Params {
  double alpha = 1.5;
  double delta0 = 4.0 / 9.0;
  double kappa = 1.0;
  double rho = 1.0 / 3.0;
};

// The paper's standard parameter set (alpha=3/2, delta0=4/9, kappa=1, rho=1/3).
inline Params paper_params() { return Params{}; }

// Throws InvalidParameter naming the first invalid parameter and its valid range.
void validate(const Params& p);

// Taylor coefficients of V (expv): V(r) = K2 r^2/2 + K3 r^3/3 + K4 r^4/4 + O(r^5).
struct TaylorCoefficients {
  double K2, K3, K4;
};
// K2 = alpha delta0^(alpha-1), K3 = -alpha(alpha-1) delta0^(alpha-2)/2,
// K4 = alpha(alpha-1)(alpha-2) delta0^(alpha-3)/6 (Sec. 2, below eq:expv).
TaylorCoefficients taylor_coefficients(const Params& p);

// Exact Hertzian force V'(r) = delta0^alpha - (delta0 - r)_+^alpha (derivative of eq:Vr).
double hertz_force(double r, double alpha, double delta0);

}  // namespace lrchain
