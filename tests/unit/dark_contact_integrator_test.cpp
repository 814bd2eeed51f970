// The contact-locating integrator of the dark-breather orbit (Sec. 5.3): an integration that does
// not continue the previous call starts from the initial step, so the same orbit gives the same
// steps and the same end state whatever the integrator did before (reproducible Newton residuals).
#include <doctest/doctest.h>

#include <cmath>
#include <vector>

#include "lrchain/ansatz/dark_breather.hpp"
#include "lrchain/errors.hpp"
#include "lrchain/sim/dark/contact_integrator.hpp"
#include "lrchain/sim/dark/resonant_chain_shooting.hpp"
#include "lrchain/sim/dark/strain_variational.hpp"

using namespace lrchain;
using namespace lrchain::sim::dark;

namespace {
// Orbit state [x y xdot ydot] at rest from the eq. (44) seed of the Fig. 17 breather (omega_b = 2.42).
std::vector<double> seed_state(Index sites) {
  const Eigen::VectorXd z0 =
      resonant_chain_dark_seed(make_dark_breather_ansatz(Params{}, Branch::optical, 2.42), DarkCenter::bond, sites);
  std::vector<double> state(static_cast<std::size_t>(4 * sites), 0.0);
  for (Index i = 0; i < z0.size(); ++i) state[static_cast<std::size_t>(i)] = z0(i);
  return state;
}
}  // namespace

TEST_CASE("contact integrator: a fresh start does not inherit the previous call's step size") {
  const Index sites = 21;
  const StrainLatticeOrbit orbit(Params{}, sites);
  const double period = 2 * 3.141592653589793 / 2.42;

  ContactIntegrator fresh(orbit);
  std::vector<double> once = seed_state(sites);
  fresh.integrate(once, 0, period);
  const Index fresh_steps = fresh.stats().steps;

  // A second integrator first runs another orbit over another interval (its last step differs from
  // the initial step), then the same orbit as above from t = 0.
  ContactIntegrator used(orbit);
  std::vector<double> other = seed_state(sites);
  for (double& v : other) v *= 0.5;
  used.integrate(other, 0, 3.7 * period);
  const Index steps_before = used.stats().steps;
  std::vector<double> again = seed_state(sites);
  used.integrate(again, 0, period);

  CHECK(used.stats().steps - steps_before == fresh_steps);  // the same step sequence ...
  CHECK(again == once);                                     // ... so bit-identical end states
}

namespace {
// x'' = -w^2 x, no contacts: w = 1e4 needs ~ 1e4 steps per time unit at the default 1e-13 tolerance
// (RKF78 at that tolerance takes several steps per radian).
struct StiffOscillator final : ContactSystem {
  double w = 1e4;
  Index dimension() const override { return 2; }
  Index stiffness_count() const override { return 0; }
  void rhs(const double* s, double* ds, double*) const override {
    ds[0] = s[1];
    ds[1] = -w * w * s[0];
  }
  Index contact_count() const override { return 0; }
  void contacts(const double*, double*, double*) const override {}
};
}  // namespace

TEST_CASE("contact integrator: more steps than max_steps_per_time allows is a NumericalFailure, the record bounded") {
  const StiffOscillator oscillator;
  ContactIntegrationOptions capped;
  capped.max_steps_per_time = 100;  // at most 1000 + 100 steps over one time unit
  ContactIntegrator integrator(oscillator, capped);
  std::vector<double> state = {1.0, 0.0};
  OrbitRecord record;
  CHECK_THROWS_AS(integrator.integrate(state, 0.0, 1.0, &record), NumericalFailure);
  CHECK(record.steps() <= 1100);
  // The same orbit with the default cap (1000 + 1e5 steps) runs: its period is 2 pi/w, and after
  // one time unit x = cos(w) (the exact solution) to the integration's accuracy.
  ContactIntegrator uncapped(oscillator);
  std::vector<double> exact = {1.0, 0.0};
  uncapped.integrate(exact, 0.0, 1.0);
  CHECK(uncapped.stats().steps > 1100);
  CHECK(exact[0] == doctest::Approx(std::cos(1e4)).epsilon(1e-6));
}
