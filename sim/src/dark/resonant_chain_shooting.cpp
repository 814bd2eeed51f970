#include "lrchain/sim/dark/resonant_chain_shooting.hpp"

#include <cmath>
#include <numbers>
#include <string>

#include "lrchain/errors.hpp"
#include "lrchain/sim/dark/tangent_propagation.hpp"

namespace lrchain::sim::dark {

ResonantChainShooting::ResonantChainShooting(const Params& p, Index sites, DarkCenter center, ShootingMode mode,
                           ContactIntegrationOptions integration)
    : p_(p), sites_(sites), center_(center), mode_(mode), integration_(integration) {
  validate(p);
  if (sites < 9 || sites % 2 == 0)
    throw InvalidParameter("sites", "must be odd and >= 9 (a staggered dark breather fits periodic "
                                    "ends only on an odd number of sites), got " +
                                        std::to_string(sites));
  const Index N = sites;
  const Index shift = center == DarkCenter::site ? 0 : 1;
  reflection_.resize(static_cast<std::size_t>(N));
  for (Index i = 0; i < N; ++i) reflection_[static_cast<std::size_t>(i)] = ((N + shift - i) % N + N) % N;
  // Orthonormal R-even / R-odd bases for both fields.
  std::vector<Eigen::VectorXd> even, odd;
  for (Index field = 0; field < 2; ++field) {
    for (Index i = 0; i < N; ++i) {
      const Index r = reflect(i);
      if (r < i) continue;
      Eigen::VectorXd e = Eigen::VectorXd::Zero(2 * N);
      if (r == i) {
        e(field * N + i) = 1.0;
        even.push_back(e);
      } else {
        const double s = std::sqrt(0.5);
        e(field * N + i) = s;
        e(field * N + r) = s;
        even.push_back(e);
        e(field * N + r) = -s;
        odd.push_back(e);
      }
    }
  }
  symmetric_.resize(2 * N, static_cast<Eigen::Index>(even.size()));
  for (std::size_t j = 0; j < even.size(); ++j) symmetric_.col(static_cast<Eigen::Index>(j)) = even[j];
  antisymmetric_.resize(2 * N, static_cast<Eigen::Index>(odd.size()));
  for (std::size_t j = 0; j < odd.size(); ++j) antisymmetric_.col(static_cast<Eigen::Index>(j)) = odd[j];
  if (center == DarkCenter::site)
    basis_ = symmetric_;
  else
    basis_ = Eigen::MatrixXd::Identity(2 * N, 2 * N);
}

double ResonantChainShooting::shooting_time(double omega_b) const {
  const double period = 2.0 * std::numbers::pi / omega_b;
  if (mode_ == ShootingMode::full) return period;
  return center_ == DarkCenter::site ? 0.5 * period : 0.25 * period;
}

void ResonantChainShooting::evaluate(const Eigen::VectorXd& q, double omega_b, Eigen::VectorXd& residual,
                            Eigen::MatrixXd* jacobian, Eigen::MatrixXd* propagator) const {
  const Index N = sites_;
  const Index k = basis_.cols();
  const Index n2 = 2 * N, n4 = 4 * N;
  const bool full_phi = propagator != nullptr;
  const bool jac = jacobian != nullptr || full_phi;
  Eigen::MatrixXd jac_storage;
  if (jacobian == nullptr && full_phi) jacobian = &jac_storage;
  const double period = 2.0 * std::numbers::pi / omega_b;
  const Eigen::VectorXd z0 = basis_ * q;

  StrainLatticeOrbit orbit(p_, N);
  std::vector<double> state(static_cast<std::size_t>(n4), 0.0);
  for (Index i = 0; i < n2; ++i) state[static_cast<std::size_t>(i)] = z0(i);
  Eigen::MatrixXd phi;
  if (jac) {
    if (full_phi) {
      phi = Eigen::MatrixXd::Identity(n4, n4);
    } else {
      phi = Eigen::MatrixXd::Zero(n4, k);
      phi.topRows(n2) = basis_;
    }
  }
  ContactIntegrator integrator(orbit, integration_);
  OrbitRecord record;
  auto advance = [&](double ta, double tb) {
    record.clear();
    integrator.integrate(state, ta, tb, jac ? &record : nullptr);
    if (jac) propagate_tangents(orbit, record, phi, 8, integration_.stop);
  };
  std::vector<double> rhs(static_cast<std::size_t>(n4));

  // Snapshot of the orbit, its time derivative, and the tangent columns at a capture time tau;
  // d(state(tau))/d(omega_b) = f(state(tau)) * dtau/domega_b = -f * tau / omega_b.
  struct Snapshot {
    Eigen::VectorXd s, f;
    Eigen::MatrixXd phi;
    double tau;
  };
  auto snapshot = [&](double tau) {
    Snapshot sn;
    sn.tau = tau;
    sn.s = Eigen::Map<const Eigen::VectorXd>(state.data(), n4);
    orbit.rhs(state.data(), rhs.data());
    sn.f = Eigen::Map<const Eigen::VectorXd>(rhs.data(), n4) * (-tau / omega_b);
    if (jac) sn.phi = full_phi ? Eigen::MatrixXd(phi.leftCols(n2) * basis_) : phi;
    return sn;
  };

  std::vector<Eigen::VectorXd> blocks;   // residual blocks
  std::vector<Eigen::MatrixXd> jblocks;  // matching Jacobian blocks (k + 1 columns)
  auto add = [&](Eigen::VectorXd r, Eigen::MatrixXd j) {
    blocks.push_back(std::move(r));
    if (jac) jblocks.push_back(std::move(j));
  };
  auto with_omega = [&](const Eigen::MatrixXd& jq, const Eigen::VectorXd& jw) {
    Eigen::MatrixXd j(jq.rows(), k + 1);
    j.leftCols(k) = jq;
    j.col(k) = jw;
    return j;
  };
  // Vertical-centre row C_x = (x_0(0) + x_0(T_b/2)) / 2 (eq:center at the far site).
  auto centre_row = [&](const Snapshot& half) {
    Eigen::VectorXd r(1);
    r(0) = 0.5 * (z0(0) + half.s(0));
    Eigen::MatrixXd j;
    if (jac) {
      Eigen::MatrixXd jq = 0.5 * (basis_.row(0) + half.phi.row(0));
      Eigen::VectorXd jw(1);
      jw(0) = 0.5 * half.f(0);
      j = with_omega(jq, jw);
    }
    add(r, j);
  };

  if (mode_ == ShootingMode::reversible && center_ == DarkCenter::site) {
    advance(0.0, 0.5 * period);
    const Snapshot h = snapshot(0.5 * period);
    // B^T Zdot(T_b/2) = 0.
    Eigen::MatrixXd j;
    if (jac) j = with_omega(symmetric_.transpose() * h.phi.bottomRows(n2),
                            symmetric_.transpose() * h.f.tail(n2));
    add(symmetric_.transpose() * h.s.tail(n2), j);
    centre_row(h);
  } else if (mode_ == ShootingMode::reversible) {
    advance(0.0, 0.25 * period);
    const Snapshot qtr = snapshot(0.25 * period);
    // (I - R) Z(T_b/4) = 0 and (I + R) Zdot(T_b/4) = 0.
    Eigen::MatrixXd j1, j2;
    if (jac) {
      j1 = with_omega(antisymmetric_.transpose() * qtr.phi.topRows(n2),
                      antisymmetric_.transpose() * qtr.f.head(n2));
      j2 = with_omega(symmetric_.transpose() * qtr.phi.bottomRows(n2),
                      symmetric_.transpose() * qtr.f.tail(n2));
    }
    add(antisymmetric_.transpose() * qtr.s.head(n2), j1);
    add(symmetric_.transpose() * qtr.s.tail(n2), j2);
    // C_x: x_0(T_b/2) = (R Z(0))_0 = x_{R(0)}(0).
    Eigen::VectorXd r(1);
    const Index r0 = reflect(0);
    r(0) = 0.5 * (z0(0) + z0(r0));
    Eigen::MatrixXd jc;
    if (jac) {
      jc = Eigen::MatrixXd::Zero(1, k + 1);
      jc.leftCols(k) = 0.5 * (basis_.row(0) + basis_.row(r0));
    }
    add(r, jc);
  } else {
    advance(0.0, 0.5 * period);
    const Snapshot h = snapshot(0.5 * period);
    advance(0.5 * period, period);
    const Snapshot f = snapshot(period);
    Eigen::MatrixXd j1, j2;
    if (jac) {
      j1 = with_omega(f.phi.topRows(n2) - basis_, f.f.head(n2));
      j2 = with_omega(f.phi.bottomRows(n2), f.f.tail(n2));
    }
    add(f.s.head(n2) - z0, j1);
    add(f.s.tail(n2), j2);
    if (center_ == DarkCenter::bond) {
      // Z(T_b/2) - R Z(0) = 0.
      Eigen::MatrixXd rb(n2, k);
      Eigen::VectorXd rz(n2);
      for (Index field = 0; field < 2; ++field)
        for (Index i = 0; i < N; ++i) {
          rb.row(field * N + i) = basis_.row(field * N + reflect(i));
          rz(field * N + i) = z0(field * N + reflect(i));
        }
      Eigen::MatrixXd j3;
      if (jac) j3 = with_omega(h.phi.topRows(n2) - rb, h.f.head(n2));
      add(h.s.head(n2) - rz, j3);
    }
    centre_row(h);
  }

  if (full_phi) *propagator = phi;
  Index rows = 0;
  for (const auto& b : blocks) rows += b.size();
  residual.resize(rows);
  if (jac) jacobian->resize(rows, k + 1);
  Index at = 0;
  for (std::size_t b = 0; b < blocks.size(); ++b) {
    residual.segment(at, blocks[b].size()) = blocks[b];
    if (jac) jacobian->middleRows(at, blocks[b].size()) = jblocks[b];
    at += blocks[b].size();
  }
}

Eigen::VectorXd resonant_chain_dark_seed(const DarkBreatherAnsatz& ansatz, DarkCenter center, Index sites) {
  std::vector<double> x, y;
  const Index half = (sites - 1) / 2;
  dark_breather_strains(ansatz, center, -half, sites, 0.0, x, y);
  Eigen::VectorXd z(2 * sites);
  for (Index i = 0; i < sites; ++i) {
    z(i) = x[static_cast<std::size_t>(i)];
    z(sites + i) = y[static_cast<std::size_t>(i)];
  }
  return z;
}

}  // namespace lrchain::sim::dark
