// Bright-breather ansatz of the focusing NLS (eq:focus_app, eq:focus_ini; Sec. 4.1).
#include "lrchain/ansatz/bright_breather.hpp"

#include <cmath>
#include <numbers>
#include <sstream>
#include <stdexcept>

#include "lrchain/errors.hpp"

namespace lrchain {

namespace {
std::string describe(double theta, const Params& p) {
  std::ostringstream s;
  s.precision(6);
  s << "theta = " << theta << ", rho = " << p.rho;
  return s.str();
}
}  // namespace

// M1, M2, a of eq:focus_app with omega_b = omega + detuning (Sec. 4.1).
BrightBreatherAnsatz::BrightBreatherAnsatz(const Params& p, Branch branch, double theta,
                                           std::optional<double> detuning, double n0)
    : params_(p), branch_(branch), nls_(coefficients(p, branch, theta)), n0_(n0) {
  if (nls_.regime == Regime::singular)
    throw InvalidParameter("theta", "the NLS coefficients are singular (resonance) at " +
                                        describe(theta, p) + "; no bright breather ansatz");
  if (nls_.regime != Regime::focusing) {
    std::ostringstream s;
    s << "the NLS is not focusing at " << describe(theta, p) << " on the " << to_string(branch)
      << " branch (omega'' h_tilde = " << nls_.curvature * nls_.h_tilde
      << " >= 0); bright breathers need omega'' h_tilde < 0";
    throw InvalidParameter("theta", s.str());
  }
  if (!std::isfinite(n0)) throw InvalidParameter("n0", "must be a finite number");
  const double d = detuning.value_or(std::copysign(kDefaultBrightDetuning, nls_.h_tilde));
  if (!(std::isfinite(d) && d * nls_.h_tilde > 0)) {
    std::ostringstream s;
    s << "omega_b - omega must be nonzero with the sign of h_tilde = " << nls_.h_tilde
      << " (here " << (nls_.h_tilde < 0 ? "< 0" : "> 0") << ")";
    throw InvalidParameter("detuning", s.str());
  }
  omega_b_ = nls_.omega + d;
  const double mu = nls_.omega - omega_b_;  // mu eps^2 = omega - omega_b
  M1_ = nls_.lambda * std::sqrt(2.0 * nls_.curvature * mu) / std::abs(nls_.h_tilde);
  M2_ = std::sqrt(2.0 * (omega_b_ - nls_.omega) / nls_.h_tilde);
  a_ = std::sqrt(2.0 * mu / nls_.curvature);
  B_ = p.kappa / (p.kappa - p.rho * nls_.omega * nls_.omega);
}

double BrightBreatherAnsatz::period() const { return 2.0 * std::numbers::pi / omega_b_; }

void BrightBreatherAnsatz::displacements(double n, double t, double& u, double& v) const {
  const double z = a_ * (n - n0_ - nls_.group_velocity * t);
  const double e1 = std::exp(-std::abs(z));
  const double e = e1 * e1;
  const double th = std::copysign((1.0 - e) / (1.0 + e), z);
  const double sech = 2.0 * e1 / (1.0 + e);
  const double osc = 2.0 * M2_ * sech * std::cos(n * nls_.theta - omega_b_ * t);
  u = M1_ * th + osc;
  v = M1_ * th + B_ * osc;
}

void BrightBreatherAnsatz::velocities(double n, double t, double& u_dot, double& v_dot) const {
  const double c = nls_.group_velocity;
  const double z = a_ * (n - n0_ - c * t);
  const double e1 = std::exp(-std::abs(z));
  const double e = e1 * e1;
  const double th = std::copysign((1.0 - e) / (1.0 + e), z);
  const double sech = 2.0 * e1 / (1.0 + e);
  const double phase = n * nls_.theta - omega_b_ * t;
  const double kink = -c * a_ * M1_ * sech * sech;
  const double osc = 2.0 * M2_ * (c * a_ * th * sech * std::cos(phase) + omega_b_ * sech * std::sin(phase));
  u_dot = kink + osc;
  v_dot = kink + B_ * osc;
}

void BrightBreatherAnsatz::strains(Index n_first, double t, std::span<double> x, std::span<double> y) const {
  if (x.size() != y.size()) throw std::invalid_argument("BrightBreatherAnsatz::strains: x and y differ in length");
  double u_prev, v_prev;
  displacements(static_cast<double>(n_first - 1), t, u_prev, v_prev);
  for (std::size_t i = 0; i < x.size(); ++i) {
    double u, v;
    displacements(static_cast<double>(n_first + static_cast<Index>(i)), t, u, v);
    x[i] = u - u_prev;
    y[i] = v - v_prev;
    u_prev = u;
    v_prev = v;
  }
}

}  // namespace lrchain
