#pragma once
// Frequency bands of the linear chain and the inverse of the dispersion relation (eq:M, eq:disp1d):
// optical band [omega_+(0), omega_+(pi)], acoustic band [0, omega_-(pi)].
#include "lrchain/dispersion.hpp"
#include "lrchain/params.hpp"

namespace lrchain::regime {

struct FrequencyBand {
  double lo = 0, hi = 0;
};

FrequencyBand frequency_band(const Params& p, Branch b);

// The highest frequency a dark-breather continuation (dark continue --omega-max) or a (delta0,
// omega) regime map (--omega-range) may reach, as a multiple of the top of the lattice's linear
// spectrum (the upper edge of the optical band, frequency_band(p, Branch::optical).hi): the
// breathers and bands of the paper stay within a few percent of a band edge, and twice the top
// also holds the second harmonic of every linear wave.
inline constexpr double max_frequency_over_spectrum_top = 2.0;

// theta in [0, pi] with omega_b(theta) = omega, from det M = 0 (eq:M) solved for
// D = 4 K2 sin^2(theta/2) = omega^2 - kappa - kappa^2 / (rho omega^2 - kappa). omega must lie
// in the band of branch b; values rounding outside [0, pi] are clamped.
double theta_of_omega(double K2, double kappa, double rho, double omega);

}  // namespace lrchain::regime
