// Unit tests of the lattice systems (eq:Hertz, eq:Hertzd0S), contact law (eq:Vr), energy (eq:edensity,
// eq:ectr) and the Odeint driver. Expected numbers come from identities stated with each check.
#include <doctest/doctest.h>

#include <cmath>
#include <numbers>
#include <random>

#include "lrchain/dispersion.hpp"
#include "lrchain/errors.hpp"
#include "lrchain/params.hpp"
#include "lrchain/sim/contact_law.hpp"
#include "lrchain/sim/displacement_lattice.hpp"
#include "lrchain/sim/energy.hpp"
#include "lrchain/sim/integrator.hpp"
#include "lrchain/sim/strain_lattice.hpp"

using namespace lrchain;
using namespace lrchain::sim;

namespace {
State random_state(std::size_t sites, double amplitude, unsigned seed) {
  std::mt19937 gen(seed);
  std::uniform_real_distribution<double> d(-amplitude, amplitude);
  State s(4 * sites);
  for (double& x : s) x = d(gen);
  return s;
}
}  // namespace

TEST_CASE("contact law matches lib hertz_force, loses contact, and V' is dV/dr" * doctest::test_suite("fast")) {
  for (double alpha : {1.5, 2.5, 1.2}) {
    Params p;
    p.alpha = alpha;
    const ContactLaw law = make_contact_law(p);
    CHECK(law.three_halves == (alpha == 1.5));
    for (double r : {-0.3, -0.01, 0.0, 0.01, 0.2, 0.44, 0.5, 1.0}) {
      CHECK(bond_force(law, r) == doctest::Approx(hertz_force(r, alpha, p.delta0)).epsilon(1e-14));
      // central difference of V (eq:Vr) reproduces V'(r)
      const double h = 1e-6;
      const double dV = (bond_energy(law, r + h) - bond_energy(law, r - h)) / (2 * h);
      CHECK(dV == doctest::Approx(bond_force(law, r)).epsilon(1e-7));
    }
    CHECK(bond_energy(law, 0.0) == doctest::Approx(0.0).scale(1.0).epsilon(1e-15));
    // beyond r = delta0 the beads separate: V'(r) = delta0^alpha (no contact force left)
    CHECK(bond_force(law, 0.6) == doctest::Approx(std::pow(p.delta0, alpha)));
  }
}

TEST_CASE("strain form equals the difference of the free-end displacement form" * doctest::test_suite("fast")) {
  // x_n = u_n - u_{n-1} on a free chain of M+1 beads satisfies eq:Hertzd0S with x_{-1}=x_M=0.
  const Params p;  // paper parameters
  const std::size_t M = 40;
  DisplacementLattice chain(p, M + 1);
  StrainLattice strain(p, M);
  State s = random_state(M + 1, 0.05, 1);
  State ds(s.size());
  chain(s, ds, 0.0);
  State xs(4 * M), dxs(4 * M);
  const auto& L = chain.layout();
  const auto& S = strain.layout();
  for (std::size_t i = 0; i < M; ++i) {
    S.primary(xs)[i] = L.primary(s)[i + 1] - L.primary(s)[i];
    S.secondary(xs)[i] = L.secondary(s)[i + 1] - L.secondary(s)[i];
    S.primary_rate(xs)[i] = L.primary_rate(s)[i + 1] - L.primary_rate(s)[i];
    S.secondary_rate(xs)[i] = L.secondary_rate(s)[i + 1] - L.secondary_rate(s)[i];
  }
  strain(xs, dxs, 0.0);
  for (std::size_t i = 0; i < M; ++i) {
    CHECK(S.primary_rate(dxs)[i] ==
          doctest::Approx(L.primary_rate(ds)[i + 1] - L.primary_rate(ds)[i]).epsilon(1e-12));
    CHECK(S.secondary_rate(dxs)[i] ==
          doctest::Approx(L.secondary_rate(ds)[i + 1] - L.secondary_rate(ds)[i]).epsilon(1e-12));
  }
}

TEST_CASE("energy density sums to the total energy, energy is conserved by rkf78 and symplectic" * doctest::test_suite("fast")) {
  const Params p;
  for (bool periodic : {false, true}) {
    DisplacementBoundary b;
    b.periodic = periodic;
    DisplacementLattice chain(p, 60, b);
    State s = random_state(60, 0.02, 7);
    std::vector<double> e(60), scratch(61);
    energy_density(chain, s, 0.0, e, scratch);
    double sum = 0;
    for (double x : e) sum += x;
    CHECK(sum == doctest::Approx(chain.total_energy(s)).epsilon(1e-13));
    const double E0 = chain.total_energy(s);
    for (auto kind : {StepperKind::rkf78, StepperKind::symplectic}) {
      State w = s;
      IntegratorOptions opt;
      opt.stepper = kind;
      opt.dt = kind == StepperKind::symplectic ? 0.01 : 0.05;
      std::vector<double> times;
      for (int k = 0; k <= 50; ++k) times.push_back(k * 1.0);
      double worst = 0;
      auto stats = integrate_observed(chain, w, times, [&](const State& st, double) {
        worst = std::max(worst, std::abs(chain.total_energy(st) - E0) / E0);
        return true;
      }, opt);
      CHECK(stats.t_reached == 50.0);
      CHECK(stats.rhs_evaluations > 0);
      // rough random data (all modes excited): rkf78 at tol 1e-12 drifts ~1.5e-10 here;
      // symplectic dt=0.01 (4th order) keeps a bounded error
      INFO("stepper ", to_string(kind), " periodic ", periodic, " drift ", worst);
      CHECK(worst < (kind == StepperKind::rkf78 ? 1e-9 : 1e-7));
    }
  }
}

TEST_CASE("small plane wave on a periodic chain oscillates at omega(theta) of eq:disp1d" * doctest::test_suite("fast")) {
  const Params p;
  const std::size_t N = 64;
  DisplacementBoundary b;
  b.periodic = true;
  DisplacementLattice chain(p, N, b);
  for (Branch br : {Branch::optical, Branch::acoustic}) {
    const double theta = 2 * std::numbers::pi * 8 / N;
    const double omega = dispersion_omega(p, br, theta);
    const double B = p.kappa / (p.kappa - p.rho * omega * omega);  // eq:b10b11
    const double eps = 1e-7;
    State s(4 * N);
    const auto& L = chain.layout();
    for (std::size_t n = 0; n < N; ++n) {
      L.primary(s)[n] = eps * std::cos(n * theta);
      L.secondary(s)[n] = B * eps * std::cos(n * theta);
      L.primary_rate(s)[n] = eps * omega * std::sin(n * theta);
      L.secondary_rate(s)[n] = B * eps * omega * std::sin(n * theta);
    }
    const State s0 = s;
    const double T = 2 * std::numbers::pi / omega;
    IntegratorOptions opt;
    opt.abs_tol = 1e-18;
    opt.rel_tol = 1e-12;
    integrate_observed(chain, s, {0.0, T}, [](const State&, double) { return true; }, opt);
    double err = 0;
    for (std::size_t n = 0; n < N; ++n)
      err = std::max(err, std::abs(L.primary(s)[n] - L.primary(s0)[n]));
    // after one linear period the mode is back: error is O(eps^2)/eps relative
    CHECK(err / eps < 1e-5);
  }
}

TEST_CASE("energy centre (eq:ectr) of a symmetric bump is its centre, window m clips" * doctest::test_suite("fast")) {
  std::vector<double> e(301, 0.0);
  for (int i = 0; i < 301; ++i) e[i] = std::exp(-0.01 * (i - 120) * (i - 120));
  CHECK(energy_centre(e, 100) == doctest::Approx(120.0).epsilon(1e-9));
  e[300] = 0.5;  // far away: outside the window m = 100 around the maximum, ignored
  CHECK(energy_centre(e, 100) == doctest::Approx(120.0).epsilon(1e-9));
}

TEST_CASE("clamped and prescribed ends: prescribed motion drives the first bead" * doctest::test_suite("fast")) {
  const Params p;
  DisplacementBoundary b;
  b.left.kind = EndKind::prescribed;
  b.left.motion = [](double t) { return 0.01 * std::sin(2.1 * t); };
  b.right.kind = EndKind::clamped;
  DisplacementLattice chain(p, 10, b);
  CHECK_FALSE(chain.autonomous());
  State s(40, 0.0), ds(40);
  chain(s, ds, 0.5);
  // u_0'' = V'(u_1-u_0) - V'(u_0 - u_ghost) = -V'(-u_ghost(t)) at rest
  CHECK(ds[20] == doctest::Approx(-bond_force(chain.law(), -0.01 * std::sin(1.05))).epsilon(1e-14));
  CHECK(ds[29] == doctest::Approx(0.0));
  DisplacementBoundary bad;
  bad.left.kind = EndKind::prescribed;
  CHECK_THROWS_AS(DisplacementLattice(p, 10, bad), InvalidParameter);
}

TEST_CASE("vectorised bond loops equal the scalar eq:Vr formulas (forces bit for bit, incl. contact loss)" * doctest::test_suite("fast")) {
  // The loops run in the AVX-512/AVX2/SSE2 clone this CPU selects. Forces (the dynamics) must give
  // the IEEE results of bond_force(); energies (diagnostics only) may differ by rounding (the
  // vectorised loop multiplies by 1/(alpha+1)): |dV| < 1e-15 for V = O(0.1).
  for (const double alpha : {1.5, 1.7}) {
    Params p;
    p.alpha = alpha;
    const ContactLaw law = make_contact_law(p);
    std::vector<double> r(1003), f(1003), V(1003), u(1004);
    for (std::size_t i = 0; i < r.size(); ++i) r[i] = -0.6 + 1.2 * double(i) / 1002.0;  // r > delta0: loss
    u[0] = 0.1;
    for (std::size_t i = 0; i < r.size(); ++i) u[i + 1] = u[i] + r[i];
    bond_forces_from_strains(law, r, f);
    bond_energies_from_strains(law, r, V);
    std::size_t force_mismatch = 0, disp_mismatch = 0;
    double energy_error = 0;
    for (std::size_t i = 0; i < r.size(); ++i) {
      force_mismatch += f[i] != bond_force(law, r[i]);
      energy_error = std::max(energy_error, std::abs(V[i] - bond_energy(law, r[i])));
    }
    bond_forces_from_displacements(law, u, f);
    for (std::size_t i = 0; i < r.size(); ++i) disp_mismatch += f[i] != bond_force(law, u[i + 1] - u[i]);
    bond_energies_from_strains(law, r, r);  // in place
    std::size_t in_place_mismatch = 0;
    for (std::size_t i = 0; i < r.size(); ++i) in_place_mismatch += r[i] != V[i];
    INFO("alpha = ", alpha);
    CHECK(force_mismatch == 0);
    CHECK(energy_error < 1e-15);
    CHECK(in_place_mismatch == 0);
    CHECK(disp_mismatch == 0);
  }
}
