#pragma once
// Time integration of a lattice system with Boost.Odeint, observed at given times:
//   rkf78      controlled Runge-Kutta-Fehlberg 7(8) (default; high accuracy per RHS evaluation)
//   dopri5     Dormand-Prince 5(4) with dense output
//   symplectic McLachlan's 4th-order symplectic RKN (fixed step `dt`, autonomous systems only)
//   srkn11b    Blanes-Moan 6th-order symplectic RKN SRKN_11^b (symplectic_rkn.hpp), autonomous only;
//   srkn14a    Blanes-Moan 6th-order SRKN_14^a
//   ss17       McLachlan's 8th-order symmetric composition SS17 of Stoermer-Verlet steps;
//              srkn11b, srkn14a, ss17 take, between consecutive observation times, the fewest
//              equal steps not longer than `dt`
// The observer is called as obs(state, t) at every requested time; it may return false to stop,
// which ends the integration at that observation time. An optional step-boundary hook is called
// at boundaries of the step sequence with the state, its time and the step size the stepper tries
// next; there a checkpoint continues the same step sequence to the last bit, and returning false
// stops the integration (an interrupt). rkf78 and the fixed-step steppers land on every observation
// time, which is then a boundary; dopri5 (dense output) steps across observation times, and its
// boundaries are its own step ends, after the observations inside the step.
// An optional stop flag (set by SIGINT/SIGTERM) is polled inside the step loops, so a run whose
// steps make little progress between observations still stops promptly: rkf78 and dopri5 stop at
// the step boundary they are at (the hook sees it, and may checkpoint there); the fixed-step
// steppers go back to the state of their last observation (a step boundary of their sequence, kept
// untouched while they step) and hand that to the hook. One relaxed atomic load per step: the loops
// stay allocation-free.
#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <boost/align/aligned_allocator.hpp>
#include <boost/numeric/odeint.hpp>

#include "lrchain/checked_number.hpp"
#include "lrchain/errors.hpp"
#include "lrchain/sim/contiguous_algebra.hpp"
#include "lrchain/sim/integrator_options.hpp"
#include "lrchain/sim/state.hpp"
#include "lrchain/sim/symplectic_rkn.hpp"

namespace lrchain::sim {

namespace detail {

inline constexpr std::int64_t max_fixed_steps = 1'000'000'000'000;  // see validate_step_count

// True if no entry is NaN or infinite (a vectorised loop: the observer calls it every sample).
bool all_finite(const double* x, std::size_t n);
// Index of the first NaN or infinite entry (n if none).
std::size_t first_non_finite(const double* x, std::size_t n);

// Wraps a system to count RHS evaluations (first-order form).
template <class System>
struct Counted {
  const System* sys;
  Index* count;
  void operator()(const State& s, State& ds, double t) const {
    ++*count;
    (*sys)(s, ds, t);
  }
};

// RKN form for symplectic steppers: dp/dt = a(q), dq/dt = p.
template <class System>
struct CountedAcceleration {
  const System* sys;
  Index* count;
  void operator()(const std::vector<double>& q, std::vector<double>& a) const {
    ++*count;
    sys->acceleration(q.data(), a.data(), 0.0);
  }
};

// Force wrapper for the Blanes-Moan steppers: Odeint calls it once per stage, in order. A stage
// whose kick b_l is 0 does not use the force (its buffer keeps earlier, finite values), and a stage
// 0 with drift a_0 = 0 sees the positions of the previous step's last stage, whose force is still in
// the stepper's buffer (first-same-as-last); neither is recomputed. FSAL reuse needs the same
// position and force buffers as the last evaluation, made at the previous call (the last stage of
// the previous step): integrate_rkn_observed owns the positions and only the stepper writes them,
// and contiguous_algebra leaves them untouched in a zero drift (q + 0 p is not even computed).
template <class System>
struct StagedAcceleration {
  struct Shared {
    const System* sys = nullptr;
    Index* count = nullptr;
    std::vector<double> kick;  // b_l per Odeint stage
    bool fsal = false;         // a_0 == 0
    std::size_t call = 0;
    const double* last_q = nullptr;  // buffers of the evaluation at the previous call, if any
    const double* last_a = nullptr;
  };
  Shared* shared;
  template <class Coor, class Deriv>
  void operator()(const Coor& q, Deriv& a) const {
    Shared& s = *shared;
    const std::size_t stages = s.kick.size();
    const std::size_t l = s.call++ % stages;
    const double* last_q = s.last_q;
    const double* last_a = s.last_a;
    s.last_q = s.last_a = nullptr;
    if (s.kick[l] == 0.0) return;
    if (l == 0 && s.fsal && last_q == q.data() && last_a == a.data()) return;
    ++*s.count;
    s.sys->acceleration(q.data(), a.data(), 0.0);
    if (s.fsal && l == stages - 1) {
      s.last_q = q.data();
      s.last_a = a.data();
    }
  }
};

// Position and momentum storage of the RKN steppers: cache-line aligned, so that the vectorised
// stage updates (contiguous_algebra) and the force loops do not split loads across cache lines.
using RknCoor = std::vector<double, boost::alignment::aligned_allocator<double, 64>>;

// The stop flag a run polls inside its step loops (null: never set).
struct StopFlag {
  const std::atomic<bool>* flag = nullptr;
  bool raised() const { return flag && flag->load(std::memory_order_relaxed); }
};

// Integrates q'' = a(q) with a Blanes-Moan stepper from times.front() through the observation
// times; each interval between observations is split into the fewest equal steps <= dt.
// `steps` and `rhs_evaluations` are counted in place, so they stay right if obs throws to stop.
// `state` holds the last observation's state while the stepper works on its own copies q, p: when
// `stop` is raised between observations, `stopped(state, t_observation)` is called with it (and
// the counts put back to that observation) and must throw.
template <class Stepper, class System, class Obs, class Stopped>
void integrate_rkn_observed(const System& system, State& state, const std::vector<double>& times,
                            Obs& obs, double dt, Index& steps,
                            Index& rhs_evaluations, StopFlag stop, Stopped& stopped) {
  namespace odeint = boost::numeric::odeint;
  const std::size_t half = state.size() / 2;
  RknCoor q(state.begin(), state.begin() + half);
  RknCoor p(state.begin() + half, state.end());
  Stepper stepper;
  typename StagedAcceleration<System>::Shared shared;
  shared.sys = &system;
  shared.count = &rhs_evaluations;
  shared.kick.assign(stepper.coef_b().begin(), stepper.coef_b().end());
  shared.fsal = stepper.coef_a()[0] == 0.0;
  StagedAcceleration<System> acc{&shared};
  for (std::size_t k = 0;; ++k) {
    obs(state, times[k]);
    if (k + 1 == times.size()) break;
    const double interval = times[k + 1] - times[k];
    const auto m = static_cast<std::size_t>(
        checked_count(interval / dt * (1 - 1e-12), "dt", 1, max_fixed_steps, "steps between observations"));
    // Odeint's integrate_n_steps (integrate/detail/integrate_n_steps.hpp), step for step, polling
    // the stop flag (the systems are autonomous: the time passed is not used).
    const double h = interval / double(m);
    const Index rhs_at_observation = rhs_evaluations;
    auto qp = std::make_pair(std::ref(q), std::ref(p));
    for (std::size_t i = 0; i < m; ++i) {
      if (stop.raised()) {
        rhs_evaluations = rhs_at_observation;
        stopped(state, times[k]);
      }
      stepper.do_step(acc, qp, times[k] + double(i) * h, h);
    }
    steps += static_cast<Index>(m);
    std::copy(q.begin(), q.end(), state.begin());
    std::copy(p.begin(), p.end(), state.begin() + half);
  }
}

struct StopIntegration {};

// Boost.Odeint's integrate_times for a controlled stepper (integrate/detail/integrate_times.hpp,
// Boost 1.74), step for step, with the step size it carries from one observation interval to the
// next handed to `boundary`, and started from `dt`: a restart from (state, t, dt) takes the same steps.
// A raised `stop` calls `stopped(x, t, dt)` at the step boundary reached (it must throw).
template <class Stepper, class System, class Obs, class Boundary, class Stopped>
void integrate_times_controlled(Stepper& st, System system, State& x, const std::vector<double>& times,
                                double dt, Obs& obs, Boundary& boundary, Index& steps, StopFlag stop,
                                Stopped& stopped) {
  namespace odeint = boost::numeric::odeint;
  odeint::failed_step_checker fail_checker;
  auto it = times.begin();
  while (true) {
    double current_time = *it++;
    obs(x, current_time);
    boundary(x, current_time, dt);
    if (it == times.end()) break;
    while (odeint::detail::less_with_sign(current_time, *it, dt)) {
      if (stop.raised()) stopped(x, current_time, dt);
      double current_dt = odeint::detail::min_abs(dt, *it - current_time);
      if (st.try_step(system, x, current_time, current_dt) == odeint::success) {
        ++steps;
        fail_checker.reset();
        dt = odeint::detail::max_abs(dt, current_dt);
      } else {
        fail_checker();
        dt = current_dt;
      }
    }
  }
}

// Boost.Odeint's integrate_times for a plain stepper (same file), counting steps in place so that
// a checkpoint written from the observer records the work done so far. A raised `stop` calls
// `stopped(t_observation, steps_at_observation)` (it must throw): the caller's copy of the state at
// the last observation is where the run can continue from.
template <class Stepper, class System, class StateType, class Obs, class Stopped>
void integrate_times_fixed(Stepper& st, System system, StateType& x, const std::vector<double>& times,
                           double dt, Obs& obs, Index& steps, StopFlag stop, Stopped& stopped) {
  namespace odeint = boost::numeric::odeint;
  double current_dt = dt;
  auto it = times.begin();
  while (true) {
    double current_time = *it++;
    obs(x, current_time);
    if (it == times.end()) break;
    const double observed_at = current_time;
    const Index steps_at_observation = steps;
    while (odeint::detail::less_with_sign(current_time, *it, current_dt)) {
      if (stop.raised()) stopped(observed_at, steps_at_observation);
      current_dt = odeint::detail::min_abs(dt, *it - current_time);
      st.do_step(system, x, current_time, current_dt);
      current_time += current_dt;
      ++steps;
    }
  }
}

// Boost.Odeint's integrate_times for a dense-output stepper (same file), with `boundary` called at
// each step end after the observations inside the step, with the stepper's current state, time and
// next step: a restart from those (initialize() recomputes the first-same-as-last derivative from the
// same state and time, the same bits) takes the same steps.
// A raised `stop` calls `stopped(state, t, dt)` at the step end reached (it must throw).
template <class Dense, class System, class Obs, class Boundary, class Stopped>
void integrate_times_dense(Dense& st, System system, State& x, const std::vector<double>& times,
                           double dt, Obs& obs, Boundary& boundary, Index& steps, StopFlag stop,
                           Stopped& stopped) {
  namespace odeint = boost::numeric::odeint;
  const double last = times.back();
  auto it = times.begin();
  st.initialize(x, *it, dt);
  obs(x, *it++);
  while (it != times.end()) {
    while (it != times.end() &&
           odeint::detail::less_eq_with_sign(*it, st.current_time(), st.current_time_step())) {
      st.calc_state(*it, x);
      obs(x, *it++);
    }
    if (it == times.end()) break;
    boundary(st.current_state(), st.current_time(), st.current_time_step());
    if (stop.raised()) stopped(st.current_state(), st.current_time(), st.current_time_step());
    if (odeint::detail::less_eq_with_sign(st.current_time() + st.current_time_step(), last,
                                          st.current_time_step())) {
      st.do_step(system);
    } else {
      st.initialize(st.current_state(), st.current_time(), last - st.current_time());
      st.do_step(system);
    }
    ++steps;
  }
}

}  // namespace detail

// A step-boundary hook: (state, t, next step size, work so far) -> continue?
using StepBoundaryHook = std::function<bool(const State&, double, double, const IntegrationStats&)>;

// Integrates `state` from times.front() through the observation times (increasing). `boundary`
// (optional) is the step-boundary hook; `resume_step` > 0 replaces opt.dt as the first step size
// of the adaptive steppers (the next_step a checkpoint recorded at times.front()). `stop`
// (optional, e.g. set by SIGINT) is polled at every step: when raised the hook is called at a step
// boundary (see the top of this file) and the integration ends with stats.stopped.
template <class System, class Observer>
IntegrationStats integrate_observed(const System& system, State& state,
                                    const std::vector<double>& times, Observer&& observer,
                                    const IntegratorOptions& opt,
                                    const StepBoundaryHook& boundary = {}, double resume_step = 0,
                                    const std::atomic<bool>* stop = nullptr) {
  namespace odeint = boost::numeric::odeint;
  validate(opt);
  IntegrationStats stats;
  if (times.empty()) return stats;
  validate_step_count(opt, times.back() - times.front());
  if constexpr (requires { system.autonomous(); })
    if (is_symplectic(opt.stepper) && !system.autonomous())
      throw InvalidParameter("stepper", std::string(to_string(opt.stepper)) +
                                            " needs an autonomous system: use rkf78 or dopri5");
  stats.t_reached = times.front();
  auto obs = [&](const State& s, double t) {
    stats.t_reached = t;
    if (!detail::all_finite(s.data(), s.size())) {
      stats.blew_up = true;
      stats.blow_up_index = static_cast<Index>(detail::first_non_finite(s.data(), s.size()));
      throw detail::StopIntegration{};
    }
    if (!observer(s, t)) { stats.stopped = true; throw detail::StopIntegration{}; }
  };
  auto at_boundary = [&](const State& s, double t, double next_step) {
    if (boundary && !boundary(s, t, next_step, stats)) {
      stats.stopped = true;
      throw detail::StopIntegration{};
    }
  };
  auto obs_at_boundary = [&](const State& s, double t) {
    obs(s, t);
    at_boundary(s, t, opt.dt);
  };
  const detail::StopFlag stop_flag{stop};
  // The stop flag was raised between observations at the step boundary (s, t, next step).
  auto stopped_at = [&](const State& s, double t, double next_step) {
    at_boundary(s, t, next_step);  // (throws when the hook stops the run)
    stats.stopped = true;
    throw detail::StopIntegration{};
  };
  // The same for the fixed-step steppers: their state at the last observation, `state`.
  auto stopped_at_observation = [&](const State& s, double t) { stopped_at(s, t, opt.dt); };
  const double first_step = resume_step > 0 ? resume_step : opt.dt;
  detail::Counted<System> rhs{&system, &stats.rhs_evaluations};
  try {
    switch (opt.stepper) {
      case StepperKind::rkf78: {
        auto stepper = odeint::make_controlled(opt.abs_tol, opt.rel_tol,
                                               odeint::runge_kutta_fehlberg78<State>());
        detail::integrate_times_controlled(stepper, rhs, state, times, first_step, obs, at_boundary,
                                           stats.steps, stop_flag, stopped_at);
        break;
      }
      case StepperKind::dopri5: {
        auto stepper = odeint::make_dense_output(opt.abs_tol, opt.rel_tol,
                                                 odeint::runge_kutta_dopri5<State>());
        detail::integrate_times_dense(stepper, rhs, state, times, first_step, obs, at_boundary,
                                      stats.steps, stop_flag, stopped_at);
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
            obs_at_boundary(state, t);
          };
          odeint::symplectic_rkn_sb3a_mclachlan<std::vector<double>> stepper;
          auto qp = std::make_pair(std::ref(q), std::ref(p));
          Index rhs_at_observation = 0;
          auto observe_pair = [&](const auto& pair, double t) {
            pair_obs(pair, t);
            rhs_at_observation = stats.rhs_evaluations;
          };
          // `state` holds the last observation (pair_obs copies q, p into it only there).
          auto stopped_fixed = [&](double t, Index steps_at_observation) {
            stats.steps = steps_at_observation;
            stats.rhs_evaluations = rhs_at_observation;
            stopped_at_observation(state, t);
          };
          detail::integrate_times_fixed(stepper, acc, qp, times, opt.dt, observe_pair, stats.steps, stop_flag,
                                        stopped_fixed);
        } else {
          throw InvalidParameter("stepper", "symplectic needs a system with acceleration()");
        }
        break;
      }
      case StepperKind::srkn11b:
      case StepperKind::srkn14a:
      case StepperKind::ss17: {
        if constexpr (requires { system.acceleration(nullptr, nullptr, 0.0); }) {
          if (opt.stepper == StepperKind::srkn11b)
            detail::integrate_rkn_observed<blanes_moan_srkn11b<detail::RknCoor, contiguous_algebra>>(
                system, state, times, obs_at_boundary, opt.dt, stats.steps, stats.rhs_evaluations, stop_flag,
                stopped_at_observation);
          else if (opt.stepper == StepperKind::srkn14a)
            detail::integrate_rkn_observed<blanes_moan_srkn14a<detail::RknCoor, contiguous_algebra>>(
                system, state, times, obs_at_boundary, opt.dt, stats.steps, stats.rhs_evaluations, stop_flag,
                stopped_at_observation);
          else
            detail::integrate_rkn_observed<mclachlan_ss17<detail::RknCoor, contiguous_algebra>>(
                system, state, times, obs_at_boundary, opt.dt, stats.steps, stats.rhs_evaluations, stop_flag,
                stopped_at_observation);
        } else {
          throw InvalidParameter("stepper", "srkn11b/srkn14a/ss17 need a system with acceleration()");
        }
        break;
      }
    }
  } catch (const detail::StopIntegration&) {
  }
  return stats;
}

}  // namespace lrchain::sim
