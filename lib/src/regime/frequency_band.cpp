#include "lrchain/regime/frequency_band.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace lrchain::regime {

// Optical band [omega_+(0), omega_+(pi)], acoustic band [0, omega_-(pi)] (eq:disp1d, Figs. 4-5).
FrequencyBand frequency_band(const Params& p, Branch b) {
  validate(p);
  const double K2 = taylor_coefficients(p).K2;
  const double top = dispersion_omega(K2, p.kappa, p.rho, b, std::numbers::pi);
  if (b == Branch::acoustic) return {0.0, top};
  return {dispersion_omega(K2, p.kappa, p.rho, b, 0.0), top};
}

// det M = 0 (eq:M): (w^2 - D - kappa)(w^2 - kappa/rho) = kappa^2/rho, solved for D.
double theta_of_omega(double K2, double kappa, double rho, double omega) {
  const double w2 = omega * omega;
  const double D = w2 - kappa - kappa * kappa / (rho * w2 - kappa);
  const double s2 = std::clamp(D / (4.0 * K2), 0.0, 1.0);
  return 2.0 * std::asin(std::sqrt(s2));
}

}  // namespace lrchain::regime
