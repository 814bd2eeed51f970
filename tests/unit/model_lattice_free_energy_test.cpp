// The energy of strain-form model lattices with open ends (model_lattice.hpp): the free chain of
// beads -1..n-1 in its centre-of-mass frame, checked against hand-written sums (fput, diatomic_chain)
// and against its conservation by a symplectic run whose waves reach both ends (fput,
// resonant_chain, diatomic_chain).
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <random>

#include "lrchain/params.hpp"
#include "lrchain/sim/integrator.hpp"
#include "lrchain/sim/model_lattice.hpp"

using namespace lrchain;
using namespace lrchain::sim;

namespace {

const lrchain_lattice_kernels& kernels(const char* name) {
  const lrchain_lattice_kernels* k = shipped_lattice_kernels(name);
  REQUIRE(k != nullptr);
  return *k;
}

// A strain and strain-velocity pulse centred on the chain, field 0 only (w = 0 for other fields).
State centred_pulse(std::size_t fields, std::size_t n, double amplitude) {
  State s(2 * fields * n, 0.0);
  const double centre = double(n - 1) / 2;
  for (std::size_t i = 0; i < n; ++i) {
    const double x = (double(i) - centre) / 2.5;
    s[i] = amplitude * std::exp(-x * x);
    s[fields * n + i] = -amplitude * x * std::exp(-x * x);  // a net momentum relative to bead -1
  }
  return s;
}

struct Drift {
  double relative;    // max |E(t) - E(0)| / E(0) over the run
  double end_energy;  // max over the run of the energy density at the two end sites
  double walls;       // the same drift of the fixed-wall displacement energy (u_0[-1] = 0 at rest)
};

// The displacement-form energy with fixed walls at both ends of the summed strains: the quantity the
// open strain form reported before its free-end energy, to show the runs below can tell them apart.
double fixed_wall_energy(const CompiledLattice& lattice, const std::vector<double>& parameters, const State& x) {
  const std::size_t m = lattice.positions();
  std::vector<double> u(m), v(m), e(lattice.sites()), work(std::size_t(lattice.kernels().workspace_size(long(lattice.sites()))));
  lattice.displacements_of(x.data(), u.data());
  lattice.displacements_of(x.data() + m, v.data());
  lattice.kernels().energy_density(parameters.data(), long(lattice.sites()), LRCHAIN_LATTICE_ENDS_FIXED, u.data(), v.data(), e.data(),
                                   work.data());
  double sum = 0;
  for (double y : e) sum += y;
  return sum;
}

// Runs srkn11b at step dt to t_end, observing the energy every time unit.
Drift energy_drift(const CompiledLattice& lattice, const std::vector<double>& parameters, State s, double dt, double t_end) {
  const double e0 = lattice.energy(s), walls0 = fixed_wall_energy(lattice, parameters, s);
  std::vector<double> e(lattice.sites()), times;
  for (double t = 0; t <= t_end; t += 1.0) times.push_back(t);
  Drift d{0.0, 0.0, 0.0};
  IntegratorOptions opt;
  opt.stepper = StepperKind::srkn11b;
  opt.dt = dt;
  integrate_observed(lattice, s, times, [&](const State& x, double) {
    d.relative = std::max(d.relative, std::abs(lattice.energy(x) - e0) / e0);
    lattice.energy_density(x.data(), x.data() + lattice.positions(), e.data());
    d.end_energy = std::max({d.end_energy, std::abs(e.front()), std::abs(e.back())});
    d.walls = std::max(d.walls, std::abs(fixed_wall_energy(lattice, parameters, x) - walls0) / walls0);
    return true;
  }, opt);
  return d;
}

}  // namespace

TEST_CASE("model lattice: open strain-form fput energy is the free-free chain's centre-of-mass energy" * doctest::test_suite("fast")) {
  const std::size_t n = 41;
  const double a = 0.25, b = 0.5;
  CompiledLattice lattice(kernels("fput"), {a, b}, n, false, LatticeForm::strain);
  std::mt19937 gen(7);
  std::uniform_real_distribution<double> d(-0.3, 0.3);
  State s(2 * n);
  for (double& x : s) x = d(gen);
  // By hand: beads -1..n-1, bond j between beads j-1 and j of strain r[j], Phi(r) = r^2/2 + a r^3/3
  // + b r^4/4 (F = Phi'), no bond beyond bead n-1; velocities relative to bead -1 (which has 0),
  // kinetic energy in the centre-of-mass frame.
  double potential = 0, momentum = 0, velocity = 0;
  std::vector<double> v(n + 1, 0.0);
  for (std::size_t j = 0; j < n; ++j) {
    const double r = s[j];
    potential += r * r / 2 + a * r * r * r / 3 + b * r * r * r * r / 4;
    velocity += s[n + j];
    v[j + 1] = velocity;
    momentum += velocity;
  }
  const double centre = momentum / double(n + 1);
  double kinetic = 0;
  for (double vk : v) kinetic += 0.5 * (vk - centre) * (vk - centre);
  CHECK(lattice.energy(s) == doctest::Approx(potential + kinetic).epsilon(1e-13));
  // The density sums to the energy.
  std::vector<double> e(n);
  lattice.energy_density(s.data(), s.data() + n, e.data());
  double sum = 0;
  for (double x : e) sum += x;
  CHECK(sum == doctest::Approx(potential + kinetic).epsilon(1e-13));
}

TEST_CASE("model lattice: open strain-form energy is conserved when waves reach both ends" * doctest::test_suite("fast")) {
  // srkn11b is symplectic of order 6 and conserves the linear momentum, so it keeps the free
  // chain's centre-of-mass energy to O(dt^6) with no secular drift: at dt = 0.01, 6000 steps, the
  // measured drift is 5e-15 (fput), 7e-14 (resonant chain) and 1.4e-13 (diatomic chain); the bound
  // 1e-8 leaves room for other compilers' rounding. The fixed-wall energy of the same runs changes
  // by 5 to 12 (relative).
  const std::size_t n = 41;
  SUBCASE("fput") {
    const std::vector<double> parameters{0.25, 0.5};
    CompiledLattice lattice(kernels("fput"), parameters, n, false, LatticeForm::strain);
    const Drift d = energy_drift(lattice, parameters, centred_pulse(1, n, 0.1), 0.01, 60.0);
    MESSAGE("fput: relative drift ", d.relative, ", fixed-wall energy drift ", d.walls);
    CHECK(d.relative < 1e-8);
    CHECK(d.walls > 1e-4);
    CHECK(d.end_energy > 1e-3 * lattice.energy(centred_pulse(1, n, 0.1)) / double(n));  // the pulse got there
  }
  SUBCASE("resonant chain (two fields, precompressed Hertz bonds kept in contact)") {
    const Params p;
    const std::vector<double> parameters{p.alpha, p.delta0, p.kappa, p.rho};
    CompiledLattice lattice(kernels("resonant_chain"), parameters, n, false, LatticeForm::strain);
    const State s = centred_pulse(2, n, 0.05 * p.delta0);
    const Drift d = energy_drift(lattice, parameters, s, 0.01, 60.0);
    MESSAGE("resonant chain: relative drift ", d.relative, ", fixed-wall energy drift ", d.walls);
    CHECK(d.relative < 1e-8);
    CHECK(d.walls > 1e-4);
    CHECK(d.end_energy > 1e-3 * lattice.energy(s) / double(n));
  }
  SUBCASE("diatomic chain (bonds v[n]-u[n] and u[n+1]-v[n]: the end bonds touch the chain on one side)") {
    const std::vector<double> parameters{1.5, 4.0 / 9.0, 2.0};
    CompiledLattice lattice(kernels("diatomic_chain"), parameters, n, false, LatticeForm::strain);
    const State s = centred_pulse(2, n, 0.05 * parameters[1]);
    const Drift d = energy_drift(lattice, parameters, s, 0.01, 60.0);
    MESSAGE("diatomic chain: relative drift ", d.relative, ", fixed-wall energy drift ", d.walls);
    CHECK(d.relative < 1e-8);
    CHECK(d.walls > 1e-4);
    CHECK(d.end_energy > 1e-3 * lattice.energy(s) / double(n));
  }
}

TEST_CASE("model lattice: open strain-form diatomic energy is the free chain's centre-of-mass energy" * doctest::test_suite("fast")) {
  // By hand: beads u_{-1}, u_0 v_0 ... u_{n-1} v_{n-1} (masses 1, 1 m 1 m ...), displacements from
  // u_{-1} = 0; Hertz bonds v_i - u_i and u_{i+1} - v_i only (u_{-1} has none), bond energy
  // Phi(r) = delta0^alpha r + ((delta0 - r)^(alpha+1) - delta0^(alpha+1))/(alpha+1) in contact;
  // kinetic energy in the centre-of-mass frame.
  const std::size_t n = 25;
  const double alpha = 1.5, delta0 = 4.0 / 9.0, m = 2;
  CompiledLattice lattice(kernels("diatomic_chain"), {alpha, delta0, m}, n, false, LatticeForm::strain);
  std::mt19937 gen(9);
  std::uniform_real_distribution<double> d(-0.1, 0.1);  // every contact kept (|argument| < delta0)
  State s(4 * n);
  for (double& x : s) x = d(gen);
  const auto Phi = [&](double r) {
    return std::pow(delta0, alpha) * r + (std::pow(delta0 - r, alpha + 1) - std::pow(delta0, alpha + 1)) / (alpha + 1);
  };
  std::vector<double> u(n), v(n), du(n), dv(n);
  double position = 0, velocity = 0;
  for (std::size_t i = 0; i < n; ++i) {
    position += s[i];
    velocity += s[2 * n + i];
    u[i] = position;
    v[i] = position + s[n + i];
    du[i] = velocity;
    dv[i] = velocity + s[3 * n + i];
  }
  double potential = 0, momentum = 0;
  for (std::size_t i = 0; i < n; ++i) {
    potential += Phi(v[i] - u[i]) + (i + 1 < n ? Phi(u[i + 1] - v[i]) : 0.0);
    momentum += du[i] + m * dv[i];
  }
  const double centre = momentum / (1 + double(n) * (1 + m));
  double kinetic = 0.5 * centre * centre;  // u_{-1}
  for (std::size_t i = 0; i < n; ++i) kinetic += 0.5 * (du[i] - centre) * (du[i] - centre) + 0.5 * m * (dv[i] - centre) * (dv[i] - centre);
  CHECK(lattice.energy(s) == doctest::Approx(potential + kinetic).epsilon(1e-12));
}
