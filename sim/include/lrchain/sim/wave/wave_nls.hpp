#pragma once
// What the NLS (eq:NLS)  i A_tau + (omega''/2) A_xixi - h_tilde |A|^2 A = 0  predicts for a travelling
// wave of first-field amplitude U (u_0 = eps (A E + c.c.), U = 2 eps |A|, E = e^{i(n theta - omega t)};
// K = eps kappa, t-rates = eps^2 tau-rates): docs/waves.md.
#include <cmath>

namespace lrchain::sim::wave {

// omega(U) - omega: the uniform envelope rotates at h |A|^2 (no mean flow on a periodic wave, as on a
// ring: h, not h_tilde; sim/ring_run.hpp).
inline double nls_frequency_shift(double h, double U) { return h * U * U / 4; }

// Modulational instability of the plane wave: sidebands e^{i kappa xi + sigma tau} grow with
// sigma^2 = P kappa^2 (2 Q a^2 - P kappa^2) for i A_tau + P A_xixi + Q |A|^2 A = 0 (P = omega''/2,
// Q = -h_tilde, a = |A|; e.g. Sulem & Sulem, The NLS equation, Sec. 3.1). In lattice units:
// sigma(K)^2 = (omega'' K^2 / 2) (-h_tilde U^2 / 2 - omega'' K^2 / 2); 0 where negative (defocusing).
inline double nls_growth_rate(double curvature, double h_tilde, double U, double K) {
  const double s2 = 0.5 * curvature * K * K * (-0.5 * h_tilde * U * U - 0.5 * curvature * K * K);
  return s2 > 0 ? std::sqrt(s2) : 0.0;
}
// The largest of them, |h_tilde| U^2 / 4 where focusing (omega'' h_tilde < 0), else 0.
inline double nls_largest_growth_rate(double curvature, double h_tilde, double U) {
  return curvature * h_tilde < 0 ? std::abs(h_tilde) * U * U / 4 : 0.0;
}
// Its K: U sqrt(|h_tilde| / (2 |omega''|)) (focusing only).
inline double nls_most_unstable_k(double curvature, double h_tilde, double U) {
  return U * std::sqrt(std::abs(h_tilde) / (2 * std::abs(curvature)));
}

}  // namespace lrchain::sim::wave
