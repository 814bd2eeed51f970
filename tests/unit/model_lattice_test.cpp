// The generated model lattices (model_lattice.hpp) against independent computations: the resonant
// chain against the hand-written strain and displacement lattices (eq:Hertzd0S, eq:Hertz), fput and
// klein_gordon against their equations of motion written out here, the Jacobian action against
// central differences, the energy against a symplectic run.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <map>
#include <random>
#include <sstream>

#include "lrchain/params.hpp"
#include "lrchain/sim/displacement_lattice.hpp"
#include "lrchain/sim/integrator.hpp"
#include "lrchain/sim/model_lattice.hpp"
#include "lrchain/sim/strain_lattice.hpp"

using namespace lrchain;
using namespace lrchain::sim;

namespace {

std::vector<double> uniform(std::size_t n, double lo, double hi, unsigned seed) {
  std::mt19937 gen(seed);
  std::uniform_real_distribution<double> d(lo, hi);
  std::vector<double> x(n);
  for (double& v : x) v = d(gen);
  return x;
}

const lrchain_lattice_kernels& kernels(const char* name) {
  const lrchain_lattice_kernels* k = shipped_lattice_kernels(name);
  REQUIRE(k != nullptr);
  return *k;
}

double max_abs(const std::vector<double>& a) {
  double m = 0;
  for (double x : a) m = std::max(m, std::abs(x));
  return m;
}

}  // namespace

TEST_CASE("model lattice: resonant chain strain form equals the specialised strain lattice, contacts lost included" * doctest::test_suite("fast")) {
  // Specialised state (x, y) = per-field strains; generated: r = x, w_n = v_n - u_n = sum_{j<=n} (y_j - x_j).
  const std::size_t n = 64;
  for (double alpha : {1.5, 2.5}) {
    Params p;
    p.alpha = alpha;
    StrainLattice reference(p, n, StrainEnds::zero_strain);
    CompiledLattice generated(kernels("resonant_chain"), {p.alpha, p.delta0, p.kappa, p.rho}, n, false, LatticeForm::strain);
    // Strains up to 0.8 > delta0 = 4/9: about a third of the bonds have lost contact.
    std::vector<double> q = uniform(2 * n, -0.3, 0.8, 11), a_ref(2 * n), a(2 * n);
    reference.acceleration(q.data(), a_ref.data());
    std::vector<double> mine(2 * n);
    double w = 0;
    for (std::size_t i = 0; i < n; ++i) {
      mine[i] = q[i];
      w += q[n + i] - q[i];
      mine[n + i] = w;
    }
    generated.acceleration(mine.data(), a.data());
    int lost = 0;
    for (std::size_t i = 0; i < n; ++i) lost += q[i] > p.delta0;
    CHECK(lost > 10);
    // r'' = x'' at every site; w''_n - w''_{n-1} = y''_n - x''_n inside. At n = 0 the two ends differ
    // by construction: the generated form holds the ghost w_{-1} = 0, the specialised one holds the
    // per-field ghost strains x_{-1} = y_{-1} = 0 and lets x_0 - y_0 move freely.
    double worst = 0;
    for (std::size_t i = 0; i < n; ++i) {
      worst = std::max(worst, std::abs(a[i] - a_ref[i]));
      if (i == 0) continue;
      const double dw = a[n + i] - a[n + i - 1];
      worst = std::max(worst, std::abs(dw - (a_ref[n + i] - a_ref[i])));
    }
    CHECK(worst < 1e-13 * std::max(1.0, max_abs(a_ref)));
  }
}

TEST_CASE("model lattice: resonant chain displacement form equals the specialised displacement lattice" * doctest::test_suite("fast")) {
  const std::size_t n = 50;
  Params p;
  for (bool periodic : {true, false}) {
    DisplacementBoundary boundary;
    boundary.periodic = periodic;
    boundary.left.kind = boundary.right.kind = EndKind::clamped;
    DisplacementLattice reference(p, n, boundary);
    CompiledLattice generated(kernels("resonant_chain"), {p.alpha, p.delta0, p.kappa, p.rho}, n, periodic, LatticeForm::displacement);
    // Displacements up to 0.4: neighbouring differences up to 0.8 > delta0, so contacts are lost.
    std::vector<double> q = uniform(2 * n, -0.4, 0.4, 5), a_ref(2 * n), a(2 * n);
    reference.acceleration(q.data(), a_ref.data(), 0.0);
    generated.acceleration(q.data(), a.data());
    double worst = 0;
    for (std::size_t i = 0; i < 2 * n; ++i) worst = std::max(worst, std::abs(a[i] - a_ref[i]));
    CHECK(worst < 1e-14);
  }
}

TEST_CASE("model lattice: fput and klein_gordon accelerations equal their equations of motion" * doctest::test_suite("fast")) {
  const std::size_t n = 40;
  const double a2 = 0.25, b3 = 0.5, C = 0.1, w0 = 1.3;
  const auto F = [&](double r) { return r + a2 * r * r + b3 * r * r * r; };  // fput: F(r) = r + a r^2 + b r^3
  for (bool periodic : {true, false}) {
    std::vector<double> u = uniform(n, -0.5, 0.5, 3), a(n);
    const auto at = [&](long i) { return i < 0 || i >= long(n) ? (periodic ? u[std::size_t((i + long(n)) % long(n))] : 0.0) : u[std::size_t(i)]; };
    CompiledLattice fput(kernels("fput"), {a2, b3}, n, periodic, LatticeForm::displacement);
    fput.acceleration(u.data(), a.data());
    double worst = 0;
    for (long i = 0; i < long(n); ++i)
      worst = std::max(worst, std::abs(a[std::size_t(i)] - (F(at(i + 1) - at(i)) - F(at(i) - at(i - 1)))));
    CHECK(worst < 1e-14);
    // klein_gordon: u'' = C (u[n+1] - 2u + u[n-1]) - (w0^2 u + a u^2 + b u^3).
    CompiledLattice kg(kernels("klein_gordon"), {C, w0, a2, b3}, n, periodic, LatticeForm::displacement);
    kg.acceleration(u.data(), a.data());
    worst = 0;
    for (long i = 0; i < long(n); ++i) {
      const double x = at(i);
      const double expected = C * (at(i + 1) - 2 * x + at(i - 1)) - (w0 * w0 * x + a2 * x * x + b3 * x * x * x);
      worst = std::max(worst, std::abs(a[std::size_t(i)] - expected));
    }
    CHECK(worst < 1e-14);
  }
  CHECK_THROWS_AS(CompiledLattice(kernels("klein_gordon"), {C, w0, a2, b3}, n, true, LatticeForm::strain), InvalidParameter);
}

TEST_CASE("model lattice: fput strain form is the difference of the displacement form" * doctest::test_suite("fast")) {
  // Periodic ring: r_n = u_n - u_{n-1} (wrapping), r_n'' = u_n'' - u_{n-1}''.
  const std::size_t n = 32;
  std::vector<double> u = uniform(n, -0.5, 0.5, 8), r(n), au(n), ar(n);
  for (std::size_t i = 0; i < n; ++i) r[i] = u[i] - u[(i + n - 1) % n];
  CompiledLattice displacement(kernels("fput"), {0.25, 0.5}, n, true, LatticeForm::displacement);
  CompiledLattice strain(kernels("fput"), {0.25, 0.5}, n, true, LatticeForm::strain);
  displacement.acceleration(u.data(), au.data());
  strain.acceleration(r.data(), ar.data());
  double worst = 0;
  for (std::size_t i = 0; i < n; ++i) worst = std::max(worst, std::abs(ar[i] - (au[i] - au[(i + n - 1) % n])));
  CHECK(worst < 1e-13);
}

TEST_CASE("model lattice: the Jacobian action equals central differences of the accelerations, every shipped model" * doctest::test_suite("fast")) {
  // Central difference error O(h^2 a''') ~ 1e-10 at h = 1e-5; states within the contacts (|q| < 0.05).
  // Every site is compared, so open strain ends check that the accelerations and the Jacobian action
  // leave out the same end bonds (the diatomic chain's v[n-1]-u[n] at both ends, for one).
  const std::size_t n = 24;
  for (const std::string& name : shipped_lattice_models()) {
    const lrchain_lattice_kernels& k = kernels(name.c_str());
    std::vector<double> parameters;
    // The defaults of models/<name>.toml, read from their kernels' names (same order).
    const std::map<std::string, double> defaults{{"alpha", 1.5}, {"delta0", 4.0 / 9.0}, {"kappa", 1}, {"rho", 1.0 / 3.0},
                                                 {"a", 0.25}, {"b", 0.5}, {"C", 0.1}, {"w0", 1}, {"m", 2},
                                                 {"k1", 1}, {"b1", -0.25}, {"g1", 0.125}, {"k2", 1}, {"b2", 0}, {"g2", 0.1}};
    for (int i = 0; i < k.parameter_count; ++i) parameters.push_back(defaults.at(k.parameter_names[i]));
    for (LatticeForm form : {LatticeForm::displacement, LatticeForm::strain}) {
      if (form == LatticeForm::strain && !k.strain_accelerations) continue;
      for (bool periodic : {true, false}) {
        CAPTURE(name);
        CAPTURE(periodic);
        CompiledLattice lattice(k, parameters, n, periodic, form);
        const std::size_t m = lattice.positions();
        std::vector<double> q = uniform(m, -0.05, 0.05, 21), dq = uniform(m, -1, 1, 22), da(m), plus(m), minus(m), qp(m), qm(m);
        const double h = 1e-5;
        for (std::size_t i = 0; i < m; ++i) {
          qp[i] = q[i] + h * dq[i];
          qm[i] = q[i] - h * dq[i];
        }
        lattice.jacobian_action(q.data(), dq.data(), da.data());
        lattice.acceleration(qp.data(), plus.data());
        lattice.acceleration(qm.data(), minus.data());
        double worst = 0;
        for (std::size_t i = 0; i < m; ++i) worst = std::max(worst, std::abs(da[i] - (plus[i] - minus[i]) / (2 * h)));
        CHECK(worst < 1e-7 * std::max(1.0, max_abs(da)));
      }
    }
  }
}

TEST_CASE("model lattice: resonant chain energy equals the specialised bond energy and is conserved by a symplectic run" * doctest::test_suite("fast")) {
  const std::size_t n = 40;
  Params p;
  CompiledLattice lattice(kernels("resonant_chain"), {p.alpha, p.delta0, p.kappa, p.rho}, n, true, LatticeForm::displacement);
  State s(4 * n, 0.0);
  // A standing wave with contact loss (bond strains up to about 0.6 > delta0).
  for (std::size_t i = 0; i < n; ++i) {
    s[i] = 0.3 * std::sin(2 * M_PI * 5 * double(i) / double(n));
    s[2 * n + i] = 0.1 * std::cos(2 * M_PI * 3 * double(i) / double(n));
  }
  // Energy by hand: sum u'^2/2 + rho v'^2/2 + kappa (u-v)^2/2 + V(u_{i+1} - u_i) (eq:Vr).
  const ContactLaw law = make_contact_law(p);
  double expected = 0;
  for (std::size_t i = 0; i < n; ++i) {
    expected += 0.5 * s[2 * n + i] * s[2 * n + i] + 0.5 * p.rho * s[3 * n + i] * s[3 * n + i] +
                0.5 * p.kappa * (s[i] - s[n + i]) * (s[i] - s[n + i]) + bond_energy(law, s[(i + 1) % n] - s[i]);
  }
  const double e0 = lattice.energy(s);
  CHECK(e0 == doctest::Approx(expected).epsilon(1e-13));
  IntegratorOptions opt;
  opt.stepper = StepperKind::srkn11b;
  opt.dt = 0.01;
  double worst = 0;
  std::vector<double> times;
  for (int i = 0; i <= 20; ++i) times.push_back(5.0 * i);
  integrate_observed(lattice, s, times, [&](const State& x, double) {
    worst = std::max(worst, std::abs(lattice.energy(x) - e0));
    return true;
  }, opt);
  // A 6th-order symplectic method at dt = 0.01: energy error bounded near 1e-10 (today's bright runs
  // reach 1e-9 relative); contact loss makes the force only C^0.5, which limits the order.
  CHECK(worst / e0 < 1e-8);
}

TEST_CASE("model lattice: open diatomic strain form is the free chain of its beads, written out by hand" * doctest::test_suite("fast")) {
  // models/diatomic_chain.toml in displacements: beads u_0 v_0 u_1 v_1 ... u_{n-1} v_{n-1} (masses 1
  // and m), Hertz bonds F(r) = delta0^alpha - max(delta0 - r, 0)^alpha of v_i - u_i and u_{i+1} - v_i;
  // free ends: no bond left of u_0 or right of v_{n-1}; bead u_{-1} (closing the strain r_0) has no
  // bond. Strain state: r_i = u_i - u_{i-1} (u_{-1} = 0), w_i = v_i - u_i.
  const std::size_t n = 30;
  const double alpha = 1.5, delta0 = 4.0 / 9.0, m = 2;
  const auto F = [&](double r) { return std::pow(delta0, alpha) - std::pow(std::max(delta0 - r, 0.0), alpha); };
  CompiledLattice lattice(kernels("diatomic_chain"), {alpha, delta0, m}, n, false, LatticeForm::strain);
  // Strains and relative displacements up to 0.6 > delta0: some contacts are lost.
  const std::vector<double> q = uniform(2 * n, -0.3, 0.6, 17);
  std::vector<double> u(n), v(n), a(2 * n);
  double position = 0;
  for (std::size_t i = 0; i < n; ++i) {
    position += q[i];
    u[i] = position;
    v[i] = position + q[n + i];
  }
  std::vector<double> force_u(n), force_v(n);
  for (std::size_t i = 0; i < n; ++i) {
    force_u[i] = F(v[i] - u[i]) - (i > 0 ? F(u[i] - v[i - 1]) : 0.0);
    force_v[i] = ((i + 1 < n ? F(u[i + 1] - v[i]) : 0.0) - F(v[i] - u[i])) / m;
  }
  lattice.acceleration(q.data(), a.data());
  double worst = 0, scale = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const double r_expected = force_u[i] - (i > 0 ? force_u[i - 1] : 0.0);  // bead u_{-1} feels no force
    worst = std::max({worst, std::abs(a[i] - r_expected), std::abs(a[n + i] - (force_v[i] - force_u[i]))});
    scale = std::max({scale, std::abs(force_u[i]), std::abs(force_v[i])});
  }
  CHECK(worst < 1e-14 * std::max(1.0, scale));
}
