#pragma once
// Time integration of a lattice system with Boost.Odeint, observed at given times:
//   rkf78      controlled Runge-Kutta-Fehlberg 7(8) (default; high accuracy per RHS evaluation)
//   dopri5     Dormand-Prince 5(4) with dense output
//   symplectic McLachlan's 4th-order symplectic RKN (fixed step `dt`, autonomous systems only)
// The observer is called as obs(state, t) at every requested time; it may return false to stop
// (e.g. on Ctrl-C), which ends the integration at that observation time.
#include <atomic>
#include <cmath>
#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

#include <boost/numeric/odeint.hpp>

#include "lrchain/errors.hpp"
#include "lrchain/sim/state.hpp"

namespace lrchain::sim {

enum class StepperKind { rkf78, dopri5, symplectic };
StepperKind parse_stepper(std::string_view text);  // throws InvalidParameter("stepper", ...)
std::string_view to_string(StepperKind k);

struct IntegratorOptions {
  StepperKind stepper = StepperKind::rkf78;
  double abs_tol = 1e-12;  // absolute local error tolerance (adaptive steppers)
  double rel_tol = 1e-12;  // relative local error tolerance (adaptive steppers)
  double dt = 0.05;        // initial step (adaptive) or fixed step (symplectic)
};
void validate(const IntegratorOptions& o);

struct IntegrationStats {
  std::size_t steps = 0;
  std::size_t rhs_evaluations = 0;
  double t_reached = 0;     // time of the last observation made
  bool stopped = false;     // the observer asked to stop (interrupt)
  bool blew_up = false;     // the state became non-finite
};

namespace detail {

// Wraps a system to count RHS evaluations (first-order form).
template <class System>
struct Counted {
  const System* sys;
  std::size_t* count;
  void operator()(const State& s, State& ds, double t) const {
    ++*count;
    (*sys)(s, ds, t);
  }
};

// RKN form for symplectic steppers: dp/dt = a(q), dq/dt = p.
template <class System>
struct CountedAcceleration {
  const System* sys;
  std::size_t* count;
  void operator()(const std::vector<double>& q, std::vector<double>& a) const {
    ++*count;
    sys->acceleration(q.data(), a.data(), 0.0);
  }
};

struct StopIntegration {};

}  // namespace detail

// Integrates `state` from times.front() through the observation times (increasing).
template <class System, class Observer>
IntegrationStats integrate_observed(const System& system, State& state,
                                    const std::vector<double>& times, Observer&& observer,
                                    const IntegratorOptions& opt) {
  namespace odeint = boost::numeric::odeint;
  validate(opt);
  IntegrationStats stats;
  if (times.empty()) return stats;
  stats.t_reached = times.front();
  auto obs = [&](const State& s, double t) {
    stats.t_reached = t;
    bool finite = true;
    for (double v : s)
      if (!std::isfinite(v)) { finite = false; break; }
    if (!finite) { stats.blew_up = true; throw detail::StopIntegration{}; }
    if (!observer(s, t)) { stats.stopped = true; throw detail::StopIntegration{}; }
  };
  detail::Counted<System> rhs{&system, &stats.rhs_evaluations};
  try {
    switch (opt.stepper) {
      case StepperKind::rkf78: {
        auto stepper = odeint::make_controlled(opt.abs_tol, opt.rel_tol,
                                               odeint::runge_kutta_fehlberg78<State>());
        stats.steps = odeint::integrate_times(stepper, rhs, state, times.begin(), times.end(),
                                              opt.dt, obs);
        break;
      }
      case StepperKind::dopri5: {
        auto stepper = odeint::make_dense_output(opt.abs_tol, opt.rel_tol,
                                                 odeint::runge_kutta_dopri5<State>());
        stats.steps = odeint::integrate_times(stepper, rhs, state, times.begin(), times.end(),
                                              opt.dt, obs);
        break;
      }
      case StepperKind::symplectic: {
        if constexpr (requires { system.acceleration(nullptr, nullptr, 0.0); }) {
          const std::size_t half = state.size() / 2;
          std::vector<double> q(state.begin(), state.begin() + half);
          std::vector<double> p(state.begin() + half, state.end());
          detail::CountedAcceleration<System> acc{&system, &stats.rhs_evaluations};
          auto pair_obs = [&](const auto& qp, double t) {
            const std::vector<double>& qq = qp.first;
            const std::vector<double>& pp = qp.second;
            std::copy(qq.begin(), qq.end(), state.begin());
            std::copy(pp.begin(), pp.end(), state.begin() + half);
            obs(state, t);
          };
          odeint::symplectic_rkn_sb3a_mclachlan<std::vector<double>> stepper;
          stats.steps = odeint::integrate_times(stepper, acc,
                                                std::make_pair(std::ref(q), std::ref(p)),
                                                times.begin(), times.end(), opt.dt, pair_obs);
        } else {
          throw InvalidParameter("stepper", "symplectic needs a system with acceleration()");
        }
        break;
      }
    }
  } catch (const detail::StopIntegration&) {
  }
  return stats;
}

}  // namespace lrchain::sim
