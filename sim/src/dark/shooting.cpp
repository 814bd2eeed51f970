// Shooting Newton residuals, variational equations and Floquet multipliers of dark breathers of
// any model file (shooting.hpp).
#include "lrchain/sim/dark/shooting.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <csignal>
#include <numbers>
#include <string>

#include <boost/numeric/odeint/stepper/generation.hpp>
#include <boost/numeric/odeint/stepper/runge_kutta_fehlberg78.hpp>
#include <boost/numeric/odeint/util/detail/less_with_sign.hpp>
#include <boost/numeric/odeint/integrate/max_step_checker.hpp>
#include <utility>

#include "lrchain/errors.hpp"
#include "lrchain/sim/dark/floquet.hpp"

namespace lrchain::sim::dark {

namespace odeint = boost::numeric::odeint;
using OrbitState = std::vector<double>;

// The orbit's stepper (the extended system's is made per call: Odeint sizes a stepper's stage
// storage once, and the number of tangent columns changes between calls).
struct DarkOrbit::Steppers {
  odeint::runge_kutta_fehlberg78<OrbitState> orbit;
  // record/replay. Odeint sizes a stepper's stage storage at its first step only (initially_resizer),
  // so it is made afresh whenever the extended size changes (replay_size: the size it was made for).
  odeint::runge_kutta_fehlberg78<OrbitState> replay;
  std::size_t replay_size = 0;
};

namespace {
// The orbit and `columns` tangents: [Z, Zdot | dZ_j, dZdot_j] -> [Zdot, Zddot | dZdot_j, J(Z) dZ_j].
void extended_rhs(const DarkOrbit& orbit, const double* s, double* ds, std::size_t columns) {
  const std::size_t P = std::size_t(orbit.positions()), n = 2 * P;
  orbit.rhs(s, ds);
  for (std::size_t j = 1; j <= columns; ++j) {
    const double* column = s + n * j;
    double* out = ds + n * j;
    std::copy(column + P, column + n, out);
    orbit.lattice().jacobian_action(s, column, out + P);
  }
}
}  // namespace

// The orbit's first-order system with the overlaps of its one-sided contacts as contact functions.
class DarkOrbit::Contacts final : public ContactSystem {
 public:
  explicit Contacts(const DarkOrbit& orbit) : orbit_(orbit) {}
  Index dimension() const override { return 2 * orbit_.positions(); }
  Index stiffness_count() const override { return 0; }
  void rhs(const double* s, double* ds, double*) const override { orbit_.rhs(s, ds); }
  Index contact_count() const override { return Index(orbit_.bonds_.size()) * orbit_.sites(); }
  void contacts(const double* s, double* value, double* rate) const override {
    contact_overlaps(orbit_.bonds_, orbit_.sites(), s, s + orbit_.positions(), value, rate);
  }

 private:
  const DarkOrbit& orbit_;
};

DarkOrbit::DarkOrbit(const lrchain_lattice_kernels& kernels, std::vector<double> parameters, Index sites,
                               bool mean_flow, ContactIntegrationOptions options, ContactBonds bonds)
    : lattice_(kernels, std::move(parameters), std::max<Index>(sites, 2), true,
               mean_flow ? LatticeForm::strain : LatticeForm::displacement),
      sites_(sites), positions_(lattice_.positions()), options_(options),
      steppers_(std::make_unique<Steppers>()), bonds_(std::move(bonds)) {
  if (sites < 9) throw InvalidParameter("sites", "must be >= 9, got " + std::to_string(sites));
  for (const auto& bond : bonds_)
    for (const auto& term : bond.terms)
      if (term.variable < 0 || term.variable >= kernels.fields)
        throw std::invalid_argument("DarkOrbit: contact bond " + bond.name + " names a variable out of range");
  if (!bonds_.empty()) {
    contacts_ = std::make_unique<Contacts>(*this);
    contact_integrator_ = std::make_unique<ContactIntegrator>(*contacts_, options_);
  }
}

DarkOrbit::~DarkOrbit() = default;

Index DarkOrbit::contact_changes() const {
  return contact_integrator_ ? contact_integrator_->stats().contact_changes : 0;
}

void DarkOrbit::rhs(const double* s, double* ds) const {
  const std::size_t P = std::size_t(positions_);
  std::copy(s + P, s + 2 * P, ds);
  lattice_.acceleration(s, ds + P);
}

// integrate_adaptive's loop for a controlled stepper, kept here so that steps can be counted,
// recorded a chunk at a time and interrupted: the same accepted steps, bit for bit.
struct DarkOrbit::AdaptiveRun {
  using Controlled = decltype(odeint::make_controlled(0.0, 0.0, 0.0, std::declval<odeint::runge_kutta_fehlberg78<OrbitState>>()));
  Controlled stepper;
  double t, t1, dt;
  std::size_t steps = 0, max_steps;
  bool ran_away = false;
  odeint::failed_step_checker fail{};
};

bool DarkOrbit::smooth_chunk(AdaptiveRun& run, std::vector<double>& state, bool record) const {
  auto system = [this](const OrbitState& s, OrbitState& ds, double) { rhs(s.data(), ds.data()); };
  times_.clear();
  steps_.clear();
  for (std::size_t k = 0; k < chunk_steps; ++k) {
    if (options_.stop && options_.stop->load(std::memory_order_relaxed)) throw Interrupted(SIGINT, "interrupted by SIGINT");
    if (!odeint::detail::less_with_sign(run.t, run.t1, run.dt)) return false;
    if (odeint::detail::less_with_sign(run.t1, run.t + run.dt, run.dt)) run.dt = run.t1 - run.t;
    const double start = run.t;
    odeint::controlled_step_result result;
    do {
      result = run.stepper.try_step(system, state, run.t, run.dt);
      run.fail();  // throws after 500 rejected trials in a row
    } while (result == odeint::fail);
    run.fail.reset();
    // An orbit that runs away (a corrector's guess beyond a polynomial force's range) oscillates ever
    // faster: a step below min_step, or more steps than max_steps, abandons it as NaN, which Newton
    // and the corrector report as a residual that is not finite.
    if ((run.t < run.t1 && run.t - start < options_.min_step) || ++run.steps > run.max_steps) {
      std::fill(state.begin(), state.end(), std::numeric_limits<double>::quiet_NaN());
      run.ran_away = true;
      times_.clear();
      steps_.clear();
      return false;
    }
    if (record) {
      times_.push_back(start);
      steps_.push_back(run.t - start);
    }
  }
  return true;
}

void DarkOrbit::integrate(std::vector<double>& state, double t0, double t1) const {
  if (contact_integrator_) {  // contact changes located; the accepted step times kept for the tangents
    record_.clear();
    contact_integrator_->integrate(state, t0, t1, &record_);
    times_.assign(record_.t.begin(), record_.t.end());
    steps_.assign(record_.dt.begin(), record_.dt.end());
    return;
  }
  AdaptiveRun run{odeint::make_controlled(options_.abs_tol, options_.rel_tol, options_.max_step, steppers_->orbit), t0,
                  t1, std::min(options_.initial_step, t1 - t0), 0,
                  1000 + std::size_t(options_.max_steps_per_time * std::max(0.0, t1 - t0))};
  while (smooth_chunk(run, state, false)) {
  }
}

// Orbit with error control first (its accepted step times, a chunk at a time for smooth models),
// then orbit and tangents together on exactly those steps: the tangents are the derivative of the
// discrete flow.
void DarkOrbit::integrate(std::vector<double>& state, Eigen::MatrixXd& phi, double t0, double t1) const {
  const std::size_t P = std::size_t(positions_), n = 2 * P, columns = std::size_t(phi.cols());
  if (phi.rows() != Eigen::Index(n)) throw std::invalid_argument("DarkOrbit: phi must have 2 positions() rows");
  auto run_away = [&] {  // the orbit ran away (above): so do its tangents
    std::fill(state.begin(), state.end(), std::numeric_limits<double>::quiet_NaN());
    phi.setConstant(std::numeric_limits<double>::quiet_NaN());
  };
  extended_.resize(n * (1 + columns));
  std::copy(state.begin(), state.end(), extended_.begin());
  for (std::size_t j = 0; j < columns; ++j)
    for (std::size_t i = 0; i < n; ++i) extended_[n * (1 + j) + i] = phi(Eigen::Index(i), Eigen::Index(j));
  auto system = [this, columns](const OrbitState& s, OrbitState& ds, double) {
    extended_rhs(*this, s.data(), ds.data(), columns);
  };
  odeint::runge_kutta_fehlberg78<OrbitState> stepper;
  auto replay = [&] {  // orbit and tangents on the recorded steps
    for (std::size_t k = 0; k < steps_.size(); ++k) {
      if (options_.stop && options_.stop->load(std::memory_order_relaxed)) throw Interrupted(SIGINT, "interrupted by SIGINT");
      stepper.do_step(system, extended_, times_[k], steps_[k]);
    }
  };
  orbit_only_.assign(state.begin(), state.end());
  if (contact_integrator_) {
    integrate(orbit_only_, t0, t1);
    if (!std::isfinite(orbit_only_.front())) return run_away();
    replay();
  } else {
    AdaptiveRun run{odeint::make_controlled(options_.abs_tol, options_.rel_tol, options_.max_step, steppers_->orbit),
                    t0, t1, std::min(options_.initial_step, t1 - t0), 0,
                    1000 + std::size_t(options_.max_steps_per_time * std::max(0.0, t1 - t0))};
    bool more = true;
    while (more) {
      more = smooth_chunk(run, orbit_only_, true);
      if (run.ran_away) return run_away();
      replay();
    }
  }
  std::copy(extended_.begin(), extended_.begin() + Eigen::Index(n), state.begin());
  for (std::size_t j = 0; j < columns; ++j)
    for (std::size_t i = 0; i < n; ++i) phi(Eigen::Index(i), Eigen::Index(j)) = extended_[n * (1 + j) + i];
}

void DarkOrbit::record(std::vector<double>& state, double t0, double t1, RecordedSteps& steps) const {
  steps.start.clear();
  steps.size.clear();
  if (contact_integrator_) {
    integrate(state, t0, t1);
    steps.start.assign(times_.begin(), times_.end());
    steps.size.assign(steps_.begin(), steps_.end());
    if (!std::isfinite(state.front())) steps.start.clear(), steps.size.clear();
    return;
  }
  AdaptiveRun run{odeint::make_controlled(options_.abs_tol, options_.rel_tol, options_.max_step, steppers_->orbit), t0,
                  t1, std::min(options_.initial_step, t1 - t0), 0,
                  1000 + std::size_t(options_.max_steps_per_time * std::max(0.0, t1 - t0))};
  bool more = true;
  while (more) {
    more = smooth_chunk(run, state, true);
    steps.start.insert(steps.start.end(), times_.begin(), times_.end());
    steps.size.insert(steps.size.end(), steps_.begin(), steps_.end());
  }
  if (run.ran_away) steps.start.clear(), steps.size.clear();
}

void DarkOrbit::replay(const RecordedSteps& steps, std::vector<double>& extended, Index columns) const {
  const std::size_t n = 2 * std::size_t(positions_), m = std::size_t(columns);
  if (extended.size() != n * (1 + m)) throw std::invalid_argument("DarkOrbit::replay: extended must have 2 positions() (1 + columns) entries");
  auto system = [this, m](const OrbitState& s, OrbitState& ds, double) { extended_rhs(*this, s.data(), ds.data(), m); };
  if (steppers_->replay_size != extended.size()) {
    steppers_->replay = odeint::runge_kutta_fehlberg78<OrbitState>();
    steppers_->replay_size = extended.size();
  }
  for (std::size_t k = 0; k < steps.size.size(); ++k) {
    if (options_.stop && options_.stop->load(std::memory_order_relaxed)) throw Interrupted(SIGINT, "interrupted by SIGINT");
    steppers_->replay.do_step(system, extended, steps.start[k], steps.size[k]);
  }
}

DarkShooting::DarkShooting(const lrchain_lattice_kernels& kernels, std::vector<double> parameters,
                                     Index sites, bool mean_flow, ShootingMode mode, ContactIntegrationOptions options,
                                     ContactBonds bonds)
    : orbit_(kernels, std::move(parameters), sites, mean_flow, options, std::move(bonds)), mean_flow_(mean_flow),
      mode_(mode) {}

std::optional<Index> DarkShooting::contact_changes_per_period(const Eigen::VectorXd& z0, double omega_b) const {
  if (orbit_.contact_bonds().empty()) return std::nullopt;
  std::vector<double> state(2 * std::size_t(orbit_.positions()), 0.0);
  std::copy(z0.data(), z0.data() + z0.size(), state.begin());
  const Index before = orbit_.contact_changes();
  orbit_.integrate(state, 0.0, 2.0 * std::numbers::pi / omega_b);
  return orbit_.contact_changes() - before;
}

OrbitAdvance DarkShooting::advance() const {
  return [this](std::vector<double>& s, double t0, double t1) { orbit_.integrate(s, t0, t1); };
}

// Residual rows (reversible: Zdot(T_b/2); full: Z(T_b) - Z(0), Zdot(T_b)), then the C_x row of
// translation-invariant models; Jacobian columns d/dq and d/domega_b (state(tau) moves with
// tau = T_b/2 or T_b: d state / d omega_b = -f(state) tau / omega_b).
void DarkShooting::evaluate(const Eigen::VectorXd& q, double omega_b, Eigen::VectorXd& residual,
                                 Eigen::MatrixXd* jacobian, Eigen::MatrixXd* propagator) const {
  const Index P = orbit_.positions(), n = 2 * P;
  const double period = 2.0 * std::numbers::pi / omega_b;
  std::vector<double> state(static_cast<std::size_t>(n), 0.0), f(static_cast<std::size_t>(n), 0.0);
  for (Index i = 0; i < P; ++i) state[std::size_t(i)] = q(i);
  const bool jac = jacobian != nullptr;
  Eigen::MatrixXd phi;
  if (jac) {
    phi = Eigen::MatrixXd::Zero(n, P);
    phi.topRows(P).setIdentity();
  }
  auto advance = [&](double t0, double t1) {
    if (jac) orbit_.integrate(state, phi, t0, t1);
    else orbit_.integrate(state, t0, t1);
  };
  const Index rows = (mode_ == ShootingMode::full ? n : P) + (mean_flow_ ? 1 : 0);
  residual.resize(rows);
  if (jac) jacobian->setZero(rows, P + 1);
  advance(0.0, 0.5 * period);
  double half_x0 = state[0], half_x0_dot = state[std::size_t(P)];
  Eigen::RowVectorXd half_row;
  if (jac) half_row = phi.row(0);
  double tau = 0.5 * period;
  if (mode_ == ShootingMode::full) {
    advance(0.5 * period, period);
    tau = period;
    for (Index i = 0; i < P; ++i) residual(i) = state[std::size_t(i)] - q(i);
  }
  const Index velocity_rows = mode_ == ShootingMode::full ? P : 0;
  for (Index i = 0; i < P; ++i) residual(velocity_rows + i) = state[std::size_t(P + i)];
  if (jac) {
    orbit_.rhs(state.data(), f.data());
    const Eigen::Map<const Eigen::VectorXd> fv(f.data(), n);
    if (mode_ == ShootingMode::full) {
      jacobian->topLeftCorner(P, P) = phi.topRows(P) - Eigen::MatrixXd::Identity(P, P);
      jacobian->col(P).head(P) = fv.head(P) * (-tau / omega_b);
    }
    jacobian->block(velocity_rows, 0, P, P) = phi.bottomRows(P);
    jacobian->col(P).segment(velocity_rows, P) = fv.tail(P) * (-tau / omega_b);
  }
  if (mean_flow_) {
    residual(rows - 1) = 0.5 * (q(0) + half_x0);  // eq:center at the far site
    if (jac) {
      jacobian->row(rows - 1).head(P) = 0.5 * half_row;
      (*jacobian)(rows - 1, 0) += 0.5;
      (*jacobian)(rows - 1, P) = 0.5 * half_x0_dot * (-0.5 * period / omega_b);
    }
  }
  if (propagator) *propagator = monodromy(q, omega_b);
}

Eigen::MatrixXd DarkShooting::monodromy(const Eigen::VectorXd& z0, double omega_b) const {
  const Eigen::Index P = orbit_.positions(), n = 2 * P;
  std::vector<double> state(std::size_t(n), 0.0);
  for (Eigen::Index i = 0; i < P; ++i) state[std::size_t(i)] = z0(i);
  Eigen::MatrixXd phi = Eigen::MatrixXd::Identity(n, n);
  orbit_.integrate(state, phi, 0.0, 2.0 * std::numbers::pi / omega_b);
  return phi;
}

void DarkShooting::jacobian_and_floquet(const Eigen::VectorXd& q, double omega_b, Eigen::VectorXd& residual,
                                             Eigen::MatrixXd& jacobian, FloquetResult* floquet) const {
  evaluate(q, omega_b, residual, &jacobian);
  if (floquet) *floquet = floquet_from_monodromy(monodromy(q, omega_b));
}

void DarkShooting::measure(const Eigen::VectorXd& z0, double omega_b, DarkMeasures& out) const {
  out = measure_dark_orbit(advance(), z0, orbit_.sites(), omega_b);
}

}  // namespace lrchain::sim::dark
