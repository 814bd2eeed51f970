#pragma once
// The steps every emitted extended-precision NLS evaluator shares (lib/include/lrchain/generated/
// and a user's model compiled at run time, whose source embeds this file's text): inputs widened
// from double and made consistent in the evaluator's arithmetic (long double or __float128) before
// the derived expressions are evaluated. Only the C++17 language, no includes: the run-time model
// compiler prepends this text to a source that is compiled with no include path.

namespace lrchain::model_evaluator {

// |x| in any arithmetic type (std::abs has no __float128 overload).
template <class Real>
inline Real magnitude(Real x) noexcept {
  return x < 0 ? -x : x;
}

// q[0..count) (double or long double) in the arithmetic type Real.
template <class From, class Real>
inline void widen(const From* q, Real* Q, int count) noexcept {
  for (int i = 0; i < count; ++i) Q[i] = q[i];
}

// D1 = 4 sin^2(theta/2) and sigma = sin(theta) = 2 sin cos from their doubles, rescaled so that
// sin^2 + cos^2 = 1 holds in Real: sigma^2 = D1 - D1^2/4, the relation the coefficients were reduced
// with (they are 0/0-like at band edges and need consistent inputs, not only close ones).
template <class Real>
inline void consistent_half_angle(double D1_in, double sigma_in, Real& D1, Real& sigma) noexcept {
  D1 = D1_in;
  sigma = sigma_in;
  if (D1_in > 0.0) {
    const Real norm = Real(0.25) * D1_in + Real(sigma_in) * sigma_in / D1_in;
    D1 = D1_in / norm;
    sigma = sigma_in / norm;
  }
}

// omega on the branch of det M = w[0] + w[1] W + ... + w[degree] W^degree = 0 (W = omega^2) through
// the double root omega_in: up to 3 Newton steps on W from omega_in^2 (stopped where a step exceeds
// 1e-6 W: not a nearby root), then 2 Newton steps on omega^2 = W.
template <class Real>
inline Real polished_omega(const Real* w, int degree, double omega_in) noexcept {
  Real w2 = Real(omega_in) * omega_in;
  for (int iteration = 0; iteration < 3; ++iteration) {
    Real p = 0, dp = 0;
    for (int k = degree; k >= 0; --k) {
      dp = dp * w2 + p;
      p = p * w2 + w[k];
    }
    const Real step = dp != 0 ? p / dp : Real(0);
    if (!(magnitude(step) <= 1e-6 * w2)) break;
    w2 -= step;
  }
  Real omega = omega_in;
  for (int iteration = 0; iteration < 2 && w2 > 0; ++iteration) omega += (w2 - omega * omega) / (2 * omega);
  return omega;
}

}  // namespace lrchain::model_evaluator
