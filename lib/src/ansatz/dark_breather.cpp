#include "lrchain/ansatz/dark_breather.hpp"

#include <cmath>
#include <numbers>
#include <string>

#include "lrchain/errors.hpp"

namespace lrchain {

std::string_view to_string(DarkCenter c) { return c == DarkCenter::site ? "site" : "bond"; }

DarkCenter parse_dark_center(std::string_view text) {
  if (text == "site") return DarkCenter::site;
  if (text == "bond") return DarkCenter::bond;
  throw InvalidParameter("center", "must be 'site' (n0 = 0) or 'bond' (n0 = 1/2), got '" +
                                       std::string(text) + "'");
}

DarkBreatherAnsatz make_dark_breather_ansatz(const Params& p, Branch edge, double omega_b) {
  validate(p);
  const NlsCoefficients c = coefficients(p, edge, std::numbers::pi);
  if (c.regime != Regime::defocusing)
    throw InvalidParameter("edge", "the theta = pi edge of the " + std::string(to_string(edge)) +
                                       " branch is not defocusing for these parameters");
  if (!(std::isfinite(omega_b) && omega_b > 0.0 && omega_b < c.omega))
    throw InvalidParameter("omega_b", "must lie in (0, " + std::to_string(c.omega) +
                                          "), below the theta = pi edge omega(pi) of the " +
                                          std::string(to_string(edge)) + " branch");
  DarkBreatherAnsatz a;
  a.edge = edge;
  a.omega_b = omega_b;
  a.omega = c.omega;
  a.curvature = c.curvature;
  a.h_tilde = c.h_tilde;
  a.lambda = c.lambda;
  const double detuning = 3.0 * (omega_b - c.omega);  // 3 (omega_b - omega) < 0
  a.amplitude = std::sqrt(detuning / c.h_tilde);
  a.inverse_width = std::sqrt(detuning / c.curvature);
  a.mean_factor = -c.lambda * std::sqrt(c.curvature * c.h_tilde) / std::abs(c.h_tilde);
  a.resonator_factor = p.kappa / (p.kappa - p.rho * c.omega * c.omega);
  return a;
}

// eq:xy_app: x_n = d^-{(m + 2 (-1)^n cos(omega_b t)) A tanh[eta (n - n0)]}, y_n likewise with the
// staggered part scaled by kappa/(kappa - rho omega^2).
void dark_breather_strains(const DarkBreatherAnsatz& a, DarkCenter center, Index n_first, Index sites,
                           double t, std::vector<double>& x, std::vector<double>& y) {
  const double n0 = dark_center_n0(center);
  const double cs = std::cos(a.omega_b * t);
  x.resize(static_cast<std::size_t>(sites));
  y.resize(static_cast<std::size_t>(sites));
  auto u = [&](Index n, double stagger) {
    const double sign = (n % 2 == 0) ? 1.0 : -1.0;
    return (a.mean_factor + 2.0 * sign * stagger * cs) * a.amplitude *
           std::tanh(a.inverse_width * (n - n0));
  };
  for (Index i = 0; i < sites; ++i) {
    const Index n = n_first + i;
    x[static_cast<std::size_t>(i)] = u(n, 1.0) - u(n - 1, 1.0);
    y[static_cast<std::size_t>(i)] = u(n, a.resonator_factor) - u(n - 1, a.resonator_factor);
  }
}

}  // namespace lrchain
