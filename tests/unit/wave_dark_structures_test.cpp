// Dark structures of a ring's energy envelope (sim/wave/dark_structures.hpp): the dark soliton of the
// defocusing NLS, |A|^2 = A0^2 [1 - d sech^2(x / l)] (black: A0^2 tanh^2(x / l)), has its full width at
// half depth 2 acosh(sqrt 2) l = 1.7627 l whatever its depth d; such a dip is one structure, a plane
// wave, a deep sinusoidal modulation (half its period below its mid level) and a thermalised ring
// (exponential site energies: the background's spread) none. A klein_gordon dark breather solved on
// its lattice (`lrchain dark solve --model klein_gordon`) is one structure as wide as its NLS seed, and
// stays one when run on its ring, oscillating at its frequency inside the band.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>
#include <vector>

#include "lrchain/jobs/dark_job.hpp"
#include "lrchain/model.hpp"
#include "lrchain/sim/model_lattice.hpp"
#include "lrchain/sim/model_lattice_bloch.hpp"
#include "lrchain/sim/integrator.hpp"
#include "lrchain/sim/wave/dark_structures.hpp"
#include "lrchain/sim/wave/wave_fate.hpp"

using namespace lrchain;
using namespace lrchain::sim::wave;

namespace {

// e_n = 1 - d sech^2((n - centre) / l) on a ring of `sites`, the nearest image of each dip.
std::vector<double> dips(Index sites, const std::vector<double>& centres, double l, double d) {
  std::vector<double> e(std::size_t(sites), 1.0);
  for (Index n = 0; n < sites; ++n)
    for (double c : centres) {
      double x = std::remainder(double(n) - c, double(sites));
      e[std::size_t(n)] -= d / std::pow(std::cosh(x / l), 2);
    }
  return e;
}

// The energy density of a ring state (positions q, velocities v) on the model's compiled lattice.
std::vector<double> ring_energy(const Model& model, const std::vector<double>& q, const std::vector<double>& v) {
  const sim::CompiledLattice ring(sim::lattice_kernels_of(model), sim::lattice_parameters(model), Index(q.size()), true,
                                  sim::LatticeForm::displacement);
  std::vector<double> e(q.size());
  ring.energy_density(q.data(), v.data(), e.data());
  return e;
}

// The full width at half depth of the dip 1 - d sech^2(x / l) after a running mean over `window` sites,
// on the continuum (bisection on the smoothed profile): what the scan's sampled, linearly interpolated
// width should approach.
double smoothed_width(double l, double d, Index window) {
  const auto f = [&](double x) {
    double s = 0;
    for (Index k = -window / 2; k <= window / 2; ++k) s += 1 / std::pow(std::cosh((x + double(k)) / l), 2);
    return 1 - d * s / double(window);
  };
  const double half = (1 + f(0)) / 2;
  double a = 0, b = 20 * l;
  for (int i = 0; i < 100; ++i) (f((a + b) / 2) < half ? a : b) = (a + b) / 2;
  return 2 * a;
}

}  // namespace

TEST_CASE("dark structures: a tanh dip is one of the NLS width, a plane wave, a modulation or a thermal ring none" *
          doctest::test_suite("fast")) {
  const Index n = 400, window = envelope_window(1.97);
  CHECK(window == 3);  // 2 pi / 1.97 = 3.19 sites
  DarkStructureScan scan(n, window);
  // A black soliton, l = 6: width 1.7627 x 6 = 10.58 sites. The 3-site running mean fills its floor to
  // d = 1 - tanh^2(1/6) 2/3 = 0.982 and so widens it to 10.81 (smoothed_width); the sampled, linearly
  // interpolated crossings add a fraction of a per cent.
  const double l = 6;
  CHECK(smoothed_width(l, 1.0, 1) == doctest::Approx(kTanhHalfDepthWidth * l).epsilon(1e-9));
  CHECK(scan.scan(dips(n, {123.0}, l, 1.0).data()) == 1);
  CHECK(scan.structures()[0].width == doctest::Approx(smoothed_width(l, 1.0, window)).epsilon(0.01));
  CHECK(scan.structures()[0].width == doctest::Approx(kTanhHalfDepthWidth * l).epsilon(0.03));
  CHECK(scan.structures()[0].depth == doctest::Approx(1 - 2.0 / 3 * std::pow(std::tanh(1 / l), 2)).epsilon(1e-3));
  CHECK(scan.structures()[0].centre == 123);
  CHECK(scan.background() == doctest::Approx(1).epsilon(1e-6));
  // Two grey ones (d = 0.7, l = 4: width 7.05, smoothed 7.41) on the same ring: two, each of its width.
  CHECK(scan.scan(dips(n, {50.0, 250.0}, 4, 0.7).data()) == 2);
  for (const DarkStructure& s : scan.structures()) CHECK(s.width == doctest::Approx(smoothed_width(4, 0.7, window)).epsilon(0.01));
  // Too shallow (d = 0.4 < kDarkDepth): none.
  CHECK(scan.scan(dips(n, {200.0}, l, 0.4).data()) == 0);

  // A plane wave at theta = 1.97: its energy density's ripple at 2 theta (10 % here) is no dip.
  std::vector<double> plane(static_cast<std::size_t>(n));
  for (Index i = 0; i < n; ++i) plane[std::size_t(i)] = 1 + 0.1 * std::cos(2 * 1.97 * double(i));
  CHECK(scan.scan(plane.data()) == 0);
  // A deep sinusoidal modulation (1 + 0.9 cos(2 pi 3 n / N))^2: its dips reach 0.01 of the maximum but
  // are half a period wide, more than kDarkWidthShare of their spacing: none.
  std::vector<double> modulated(static_cast<std::size_t>(n));
  for (Index i = 0; i < n; ++i)
    modulated[std::size_t(i)] = std::pow(1 + 0.9 * std::cos(2 * std::numbers::pi * 3 * double(i) / double(n)), 2);
  CHECK(scan.scan(modulated.data()) == 0);
  // A thermalised ring: exponential site energies; a 3-site mean is Gamma(3) distributed, below half its
  // median 2.674 with probability 0.15 (its distribution function at 1.337), so the dips and their flanks
  // leave no intact background (and what is left spreads like Gamma(3): (q3 - q1) / b = 0.73).
  std::mt19937_64 random(7);
  std::exponential_distribution<double> gibbs(1.0);
  std::vector<double> thermal(static_cast<std::size_t>(n));
  for (double& x : thermal) x = gibbs(random);
  CHECK(scan.scan(thermal.data()) == 0);
  CHECK_FALSE(scan.background_spread() <= kDarkBackgroundSpread);
}

TEST_CASE("dark structures: a klein_gordon dark breather is one, as wide as its NLS seed" * doctest::test_suite("fast")) {
  // klein_gordon with b = -1/2 is defocusing at its theta = pi edge omega = sqrt(1.4) = 1.1832
  // (docs/dark-models.md); omega_b = 1.178 lies 0.005 below it, on an odd ring of 81 sites.
  const Model model = shipped_model("klein_gordon", {{"b", -0.5}});
  jobs::dark::DarkConfig c;
  c.step = jobs::dark::DarkStep::solve;
  c.model = &model;
  c.kernels = sim::shipped_lattice_kernels("klein_gordon");
  c.omega_b = 1.178;
  c.sites = 81;
  jobs::dark::validate(c);
  const jobs::dark::DarkResult r = jobs::dark::run(c);
  REQUIRE(r.newton.converged);
  const Index n = *c.sites;
  const std::vector<double> rest(std::size_t(n), 0.0);  // Z(0) is a turning point: every velocity 0
  const std::vector<double> solved(r.z0.data(), r.z0.data() + n), seed(r.seed.data(), r.seed.data() + n);
  DarkStructureScan scan(n, envelope_window(std::numbers::pi));
  REQUIRE(scan.scan(ring_energy(model, seed, rest).data()) == 1);
  const DarkStructure expected = scan.structures()[0];
  REQUIRE(scan.scan(ring_energy(model, solved, rest).data()) == 1);
  const DarkStructure found = scan.structures()[0];
  // The NLS seed and the exact breather agree to O(eps) near the edge: the width within 10 %, the depth
  // near 1 (a black soliton: the envelope through 0 at the phase defect), the same centre.
  CHECK(found.width == doctest::Approx(expected.width).epsilon(0.1));
  CHECK(found.depth > 0.9);
  CHECK(std::abs(std::remainder(found.centre - expected.centre, double(n))) <= 1);
  CHECK(scan.background_spread() < kDarkBackgroundSpread);

  // The breather run on its ring (srkn11b, 40 steps a period, 24 periods): one structure at every period,
  // and the velocity at its half-depth edge oscillates at omega_b, inside the branch's band [w0, sqrt(w0^2 +
  // 4 C)] = [1, sqrt(1.4)] (omega^2 = w0^2 + 4 C sin^2(theta / 2)): a dark breather, not a gap one.
  const sim::CompiledLattice ring(sim::lattice_kernels_of(model), sim::lattice_parameters(model), n, true,
                                  sim::LatticeForm::displacement);
  sim::State state(std::size_t(2 * n), 0.0);
  std::copy(solved.begin(), solved.end(), state.begin());
  const double period = 2 * std::numbers::pi / c.omega_b;
  const Index periods = 24, per = kSamplesPerPeriod, edge = Index(std::lround(found.right)) % n;
  std::vector<double> times, edge_velocity, e(static_cast<std::size_t>(n));
  for (Index k = 0; k <= periods * per; ++k) times.push_back(double(k) * period / double(per));
  Index counted = 0, observations = 0;
  sim::IntegratorOptions opt;
  opt.stepper = sim::StepperKind::srkn11b;
  opt.dt = period / 40;
  sim::integrate_observed(ring, state, times, [&](const sim::State& x, double) {
    if (observations++ % per == 0) {
      ring.energy_density(x.data(), x.data() + n, e.data());
      counted += scan.scan(e.data()) == 1;
    }
    edge_velocity.push_back(x[std::size_t(n + edge)]);
    return true;
  }, opt);
  CHECK(counted == periods + 1);
  const double omega = zero_crossing_frequency(edge_velocity.data(), Index(edge_velocity.size()), 1, period / double(per));
  CHECK(omega == doctest::Approx(c.omega_b).epsilon(1e-3));
  const auto band = sim::branch_band(sim::lattice_kernels_of(model), sim::lattice_parameters(model), 0);
  CHECK(band[0] == doctest::Approx(1.0).epsilon(1e-12));
  CHECK(band[1] == doctest::Approx(std::sqrt(1.4)).epsilon(1e-12));
  CHECK(omega > band[0]);
  CHECK(omega < band[1]);
}
