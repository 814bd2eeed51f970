// Shooting residual and Jacobian of a model's dark breather in its reflection family
// (symmetric_shooting.hpp).
#include "lrchain/sim/dark/symmetric_shooting.hpp"

#include <numbers>
#include <vector>

#include "lrchain/sim/dark/floquet.hpp"

namespace lrchain::sim::dark {

SymmetricDarkShooting::SymmetricDarkShooting(const DarkShooting& shooting, LatticeReflection reflection)
    : shooting_(shooting), reflection_(std::move(reflection)), even_(reflection_even_basis(reflection_)),
      odd_(reflection_odd_basis(reflection_)) {
  const Index P = shooting_.unknowns();
  basis_ = reflection_.half_period ? Eigen::MatrixXd::Identity(P, P) : even_;
  center_row_ = shooting_.mean_flow() && reflection_.sign.front() > 0;
}

// Rows: (half period) the R-odd part of Z(T_b/4) and the R-even part of Zdot(T_b/4), or (at all times)
// the R-even part of Zdot(T_b/2); then the C_x row. Columns d/dq and d/domega_b (the state at
// tau = T_b/4 or T_b/2 moves with tau: d state/d omega_b = -f(state) tau/omega_b).
void SymmetricDarkShooting::evaluate(const Eigen::VectorXd& q, double omega_b, Eigen::VectorXd& residual,
                                     Eigen::MatrixXd* jacobian, Eigen::MatrixXd* propagator) const {
  const DarkOrbit& orbit = shooting_.orbit();
  const Index P = orbit.positions(), n = 2 * P, k = unknowns();
  const double period = 2.0 * std::numbers::pi / omega_b;
  const bool half = reflection_.half_period;
  const double tau = half ? 0.25 * period : 0.5 * period;
  const Eigen::VectorXd z0 = basis_ * q;
  std::vector<double> state(std::size_t(n), 0.0), f(std::size_t(n), 0.0);
  for (Index i = 0; i < P; ++i) state[std::size_t(i)] = z0(i);
  Eigen::MatrixXd phi;
  if (jacobian) {
    phi = Eigen::MatrixXd::Zero(n, k);
    phi.topRows(P) = basis_;
    orbit.integrate(state, phi, 0.0, tau);
  } else {
    orbit.integrate(state, 0.0, tau);
  }
  const Eigen::Map<const Eigen::VectorXd> position(state.data(), P), velocity(state.data() + P, P);
  const Index first = half ? Index(odd_.cols()) : 0;  // rows before the velocity rows
  const Index rows = first + Index(even_.cols()) + (center_row_ ? 1 : 0);
  residual.resize(rows);
  if (half) residual.head(first) = odd_.transpose() * position;
  residual.segment(first, even_.cols()) = even_.transpose() * velocity;
  if (jacobian) {
    jacobian->setZero(rows, k + 1);
    orbit.rhs(state.data(), f.data());
    const Eigen::Map<const Eigen::VectorXd> fv(f.data(), n);
    if (half) {
      jacobian->topLeftCorner(first, k) = odd_.transpose() * phi.topRows(P);
      jacobian->col(k).head(first) = odd_.transpose() * fv.head(P) * (-tau / omega_b);
    }
    jacobian->block(first, 0, even_.cols(), k) = even_.transpose() * phi.bottomRows(P);
    jacobian->col(k).segment(first, even_.cols()) = even_.transpose() * fv.tail(P) * (-tau / omega_b);
  }
  if (center_row_) {
    // eq:center at the far site: C_x = (x_0(0) + x_0(T_b/2))/2, with x(T_b/2) = R x(0) (half period)
    // or the orbit's own x_0(T_b/2) = x_0(tau).
    const Index last = rows - 1;
    if (half) {
      const Index from = reflection_.image[0];  // (R z)_0 = sign z_from, image(from) = 0
      residual(last) = 0.5 * (z0(0) + reflection_.sign[std::size_t(from)] * z0(from));
      if (jacobian) {
        jacobian->row(last).head(k) = 0.5 * (basis_.row(0) + reflection_.sign[std::size_t(from)] * basis_.row(from));
      }
    } else {
      residual(last) = 0.5 * (z0(0) + state[0]);
      if (jacobian) {
        jacobian->row(last).head(k) = 0.5 * (basis_.row(0) + phi.row(0));
        (*jacobian)(last, k) = 0.5 * state[std::size_t(P)] * (-tau / omega_b);
      }
    }
  }
  if (propagator) *propagator = shooting_.monodromy(z0, omega_b);
}

void SymmetricDarkShooting::jacobian_and_floquet(const Eigen::VectorXd& q, double omega_b, Eigen::VectorXd& residual,
                                                 Eigen::MatrixXd& jacobian, FloquetResult* floquet) const {
  evaluate(q, omega_b, residual, &jacobian);
  if (floquet) *floquet = floquet_from_monodromy(shooting_.monodromy(basis_ * q, omega_b));
}

void SymmetricDarkShooting::measure(const Eigen::VectorXd& z0, double omega_b, DarkMeasures& out) const {
  shooting_.measure(z0, omega_b, out);
}

std::optional<Index> SymmetricDarkShooting::contact_changes_per_period(const Eigen::VectorXd& z0,
                                                                       double omega_b) const {
  return shooting_.contact_changes_per_period(z0, omega_b);
}

}  // namespace lrchain::sim::dark
