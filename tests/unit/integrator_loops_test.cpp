// integrate_observed's own observation loops (rkf78, dopri5, McLachlan) are Boost.Odeint's
// integrate_times with the step size exposed at step boundaries: they must observe the same states
// to the last bit as odeint::integrate_times itself (expected value: Boost's function).
#include <doctest/doctest.h>

#include <boost/numeric/odeint.hpp>
#include <cmath>
#include <cstring>
#include <vector>

#include "lrchain/params.hpp"
#include "lrchain/sim/displacement_lattice.hpp"
#include "lrchain/sim/integrator.hpp"

using namespace lrchain;
using namespace lrchain::sim;

namespace {

// A localised bump on a 24-bead free chain, observed at 13 irregular times.
struct Setup {
  DisplacementLattice chain{Params{}, 24};
  State s0;
  std::vector<double> times{0, 0.3, 0.31, 1.0, 2.5, 2.75, 4, 4.125, 6, 7.7, 9, 11.5, 12};
  Setup() : s0(chain.layout().size(), 0.0) {
    const auto& L = chain.layout();
    for (std::size_t i = 0; i < 24; ++i) {
      const double d = double(i) - 11.5;
      L.primary(s0)[i] = 0.05 * std::exp(-d * d / 8);
      L.primary_rate(s0)[i] = 0.02 * d * std::exp(-d * d / 8);
    }
  }
};

std::vector<double> observed_by_integrate_observed(const Setup& x, const IntegratorOptions& opt) {
  State s = x.s0;
  std::vector<double> all;
  integrate_observed(x.chain, s, x.times, [&](const State& st, double) {
    all.insert(all.end(), st.begin(), st.end());
    return true;
  }, opt);
  return all;
}

bool same_bits(const std::vector<double>& a, const std::vector<double>& b) {
  return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(double)) == 0;
}

}  // namespace

TEST_CASE("integrate_observed's rkf78 and dopri5 loops observe the states of odeint::integrate_times bit for bit") {
  namespace odeint = boost::numeric::odeint;
  const Setup x;
  IntegratorOptions opt;
  opt.abs_tol = opt.rel_tol = 1e-9;
  opt.dt = 0.07;
  auto rhs = [&x](const State& s, State& ds, double t) { x.chain(s, ds, t); };
  for (StepperKind k : {StepperKind::rkf78, StepperKind::dopri5}) {
    CAPTURE(to_string(k));
    opt.stepper = k;
    State s = x.s0;
    std::vector<double> boost_states;
    auto obs = [&](const State& st, double) { boost_states.insert(boost_states.end(), st.begin(), st.end()); };
    if (k == StepperKind::rkf78) {
      auto stepper = odeint::make_controlled(opt.abs_tol, opt.rel_tol, odeint::runge_kutta_fehlberg78<State>());
      odeint::integrate_times(stepper, rhs, s, x.times.begin(), x.times.end(), opt.dt, obs);
    } else {
      auto stepper = odeint::make_dense_output(opt.abs_tol, opt.rel_tol, odeint::runge_kutta_dopri5<State>());
      odeint::integrate_times(stepper, rhs, s, x.times.begin(), x.times.end(), opt.dt, obs);
    }
    const auto ours = observed_by_integrate_observed(x, opt);
    REQUIRE(boost_states.size() == x.times.size() * x.s0.size());
    CHECK(same_bits(ours, boost_states));
  }
}

TEST_CASE("integrate_observed's McLachlan loop observes the states of odeint::integrate_times bit for bit") {
  namespace odeint = boost::numeric::odeint;
  const Setup x;
  IntegratorOptions opt;
  opt.stepper = StepperKind::symplectic;
  opt.dt = 0.05;
  const std::size_t half = x.s0.size() / 2;
  std::vector<double> q(x.s0.begin(), x.s0.begin() + long(half)), p(x.s0.begin() + long(half), x.s0.end());
  auto acc = [&x](const std::vector<double>& qq, std::vector<double>& a) { x.chain.acceleration(qq.data(), a.data(), 0.0); };
  std::vector<double> boost_states;
  auto obs = [&](const auto& qp, double) {
    const std::vector<double>& qq = qp.first;
    const std::vector<double>& pp = qp.second;
    boost_states.insert(boost_states.end(), qq.begin(), qq.end());
    boost_states.insert(boost_states.end(), pp.begin(), pp.end());
  };
  odeint::symplectic_rkn_sb3a_mclachlan<std::vector<double>> stepper;
  odeint::integrate_times(stepper, acc, std::make_pair(std::ref(q), std::ref(p)), x.times.begin(),
                          x.times.end(), opt.dt, obs);
  CHECK(same_bits(observed_by_integrate_observed(x, opt), boost_states));
}
