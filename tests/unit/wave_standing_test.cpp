// Standing waves (sim/wave/standing_wave.hpp through the wave job, docs/waves.md "Standing waves"): the
// small-amplitude frequency of fput's and Klein-Gordon's standing waves against a Lindstedt-Poincare
// expansion done here in Fourier space (independent of the solver's collocation in time), the orbit
// closing after one period in a direct ring run, the reflection found in a two-field cell, and the refusals.
#include <doctest/doctest.h>

#include <cmath>
#include <complex>
#include <functional>
#include <map>
#include <numbers>
#include <utility>

#include <boost/numeric/odeint.hpp>

#include "lrchain/errors.hpp"
#include "lrchain/jobs/wave_job.hpp"
#include "lrchain/model.hpp"
#include "lrchain/sim/model_lattice_bloch.hpp"

using namespace lrchain;
using namespace lrchain::jobs::wave;
using cd = std::complex<double>;

namespace {

WaveConfig standing_config(const Model& model, const char* branch, double theta, double amplitude, Index sites) {
  WaveConfig c;
  c.step = WaveStep::standing;
  c.model = &model;
  c.kernels = &sim::lattice_kernels_of(model);
  c.branch = branch;
  c.theta = theta;
  c.amplitude = amplitude;
  c.ring_sites = sites;
  return c;
}

// One-field lattice u'' = L u + s_out(k) (a q^2 + b q^3), q = s_in(k) u, L e^{ikn} = -Omega2(k) e^{ikn}. The
// standing wave u1 = A cos(theta n) cos(omega t) = (A/4) sum over the four (+-theta, +-omega) exponentials;
// second order: u2 = a s_out q1^2 / (Omega2(k) - (m omega)^2) mode by mode (the mode k = 0 of a
// translation-invariant model, s_out = 0, is left out); third order: the part of s_out (2a q1 q2 + b q1^3)
// on e^{i(theta n + omega t)}, whose solvability gives omega^2 - Omega2(theta) = -4 N / A. Returns omega - Omega.
struct OneFieldLattice {
  std::function<double(double)> omega2;
  std::function<cd(double)> s_in, s_out;
  double a, b;
};
double lindstedt_standing_shift(const OneFieldLattice& m, double theta, double A) {
  using Modes = std::map<std::pair<int, int>, cd>;  // (multiple of theta, multiple of omega) -> coefficient
  const double omega = std::sqrt(m.omega2(theta));
  Modes u1;
  for (int s : {1, -1})
    for (int t : {1, -1}) u1[{s, t}] = A / 4;
  const auto q_of = [&](const Modes& u) {
    Modes q;
    for (const auto& [km, c] : u) q[km] = c * m.s_in(km.first * theta);
    return q;
  };
  const auto times = [](const Modes& x, const Modes& y) {
    Modes r;
    for (const auto& [k1, c1] : x)
      for (const auto& [k2, c2] : y) r[{k1.first + k2.first, k1.second + k2.second}] += c1 * c2;
    return r;
  };
  const Modes q1 = q_of(u1), q1q1 = times(q1, q1);
  Modes u2;
  for (const auto& [km, c] : q1q1) {
    const cd out = m.s_out(km.first * theta);
    if (std::abs(out) < 1e-14) continue;
    u2[km] = m.a * out * c / (m.omega2(km.first * theta) - std::pow(km.second * omega, 2));
  }
  const Modes cross = times(q1, q_of(u2)), cube = times(q1, q1q1);
  const std::pair<int, int> carrier{1, 1};
  const cd N = m.s_out(theta) * (2 * m.a * (cross.count(carrier) ? cross.at(carrier) : 0.0) +
                                 m.b * (cube.count(carrier) ? cube.at(carrier) : 0.0));
  return (-4.0 * N.real() / A) / (2 * omega);
}

const OneFieldLattice fput_lattice{[](double k) { return 4 * std::pow(std::sin(k / 2), 2); },
                                   [](double k) { return std::exp(cd(0, k)) - 1.0; },
                                   [](double k) { return 1.0 - std::exp(cd(0, -k)); }, 0.25, 0.5};
const OneFieldLattice klein_gordon_lattice{[](double k) { return 1 + 0.4 * std::pow(std::sin(k / 2), 2); },
                                           [](double) { return cd(1); }, [](double) { return cd(-1); }, 0.25, 0.5};

}  // namespace

TEST_CASE("wave standing: the small-amplitude frequency of fput and Klein-Gordon is the Lindstedt-Poincare shift" *
          doctest::test_suite("fast")) {
  // fput: F(r) = r + r^2/4 + r^3/2; klein_gordon: C = 1/10, w0 = 1, a = 1/4, b = 1/2 (models/*.toml).
  for (const auto& [name, lattice] : {std::pair{"fput", fput_lattice}, std::pair{"klein_gordon", klein_gordon_lattice}}) {
    const Model model = shipped_model(name);
    WaveConfig c = standing_config(model, "", 2 * std::numbers::pi / 5, 0.02, 20);
    c.ramp = 2;  // A = 0.01, 0.02
    const WaveResult r = run(c);
    REQUIRE(!r.failure);
    REQUIRE(r.standing.size() == 2);
    double previous_error = 0;
    for (const auto& w : r.standing) {
      const double expected = lindstedt_standing_shift(lattice, r.theta, w.amplitude);
      const double error = std::abs((w.omega - w.omega_linear) / expected - 1);
      MESSAGE(std::string(name) << " A " << w.amplitude << ": shift " << w.omega - w.omega_linear << ", Lindstedt " << expected
                   << ", rel " << error << ", travelling h A^2/4 " << r.nls.h * w.amplitude * w.amplitude / 4);
      CHECK(error < 5e-4);
      if (previous_error > 0) CHECK(error > 3 * previous_error);  // the next term is O(A^4): doubling A quadruples it
      previous_error = error;
      // Not the travelling wave's shift h A^2/4 (the counter-propagating waves interact).
      CHECK(std::abs(r.nls.h * w.amplitude * w.amplitude / 4 - expected) > 0.1 * std::abs(expected));
    }
    REQUIRE(r.standing_floquet);
    CHECK(r.standing_floquet->stable);  // a small standing wave on 20 sites: every multiplier on the unit circle
    CHECK(r.standing_floquet->largest_modulus == doctest::Approx(1).epsilon(1e-6));
  }
}

TEST_CASE("wave standing: a ring run of the solved wave closes after one period" * doctest::test_suite("fast")) {
  const Model model = shipped_model("resonant_chain", {{"rho", 0.32}, {"delta0", 0.27}});
  const WaveResult r = run(standing_config(model, "acoustic", 2 * std::numbers::pi / 5, 0.03, 10));
  REQUIRE(!r.failure);
  const auto& w = r.standing.back();
  CHECK(r.reflection->sign == -1);  // u_f[n] -> -u_f[-n]: the strains mirror
  sim::CompiledLattice ring(sim::lattice_kernels_of(model), sim::lattice_parameters(model), w.sites, true,
                         sim::LatticeForm::displacement);
  Eigen::VectorXd q;
  sim::wave::standing_positions(w, w.sites, 0.0, q);
  std::vector<double> state(std::size_t(2 * q.size()), 0.0);  // even in t: at rest at t = 0
  std::copy(q.data(), q.data() + q.size(), state.begin());
  const double period = 2 * std::numbers::pi / w.omega;
  namespace odeint = boost::numeric::odeint;
  odeint::integrate_adaptive(odeint::make_controlled<odeint::runge_kutta_dopri5<std::vector<double>>>(1e-12, 1e-12),
                             [&](const std::vector<double>& s, std::vector<double>& ds, double) {
                               const std::size_t P = std::size_t(q.size());
                               std::copy(s.begin() + long(P), s.end(), ds.begin());
                               ring.acceleration(s.data(), ds.data() + P);
                             },
                             state, 0.0, period, period / 100);
  double returned = 0;
  for (Index p = 0; p < q.size(); ++p) returned = std::max(returned, std::abs(state[std::size_t(p)] - q(p)));
  MESSAGE("max |u(T) - u(0)| / A = " << returned / w.amplitude << " (omega shift " << w.omega - w.omega_linear << ")");
  CHECK(returned / w.amplitude < 1e-7);  // at the linear frequency it would miss by ~ |omega shift| T = 1e-3
}

TEST_CASE("wave standing: refusals where there is no standing wave" * doctest::test_suite("fast")) {
  const Model fput = shipped_model("fput");
  // theta moving to pi (or 0) on the ring: the counter-propagating waves are one wave.
  for (double theta : {3.1, 0.05}) {
    try {
      run(standing_config(fput, "", theta, 0.01, 20));
      FAIL("accepted theta " << theta);
    } catch (const InvalidParameter& e) {
      CHECK(e.parameter() == "theta");
    }
  }
  // The diatomic chain's cell is symmetric about a bond: found with an offset of its second field.
  const Model diatomic = shipped_model("diatomic_chain");
  const WaveResult d = run(standing_config(diatomic, "acoustic", 2 * std::numbers::pi / 5, 0.02, 10));
  REQUIRE(d.reflection);
  CHECK(d.reflection->offsets == std::vector<int>{0, -1});
  // The paper's chain at an amplitude where its contacts open: a failure with the reason, not a number.
  const Model chain = shipped_model("resonant_chain", {{"rho", 0.32}, {"delta0", 0.27}});
  const WaveResult r = run(standing_config(chain, "acoustic", 2 * std::numbers::pi / 5, 0.4, 10));
  REQUIRE(r.failure);
  CHECK(r.failure->find("contact") != std::string::npos);
  CHECK(*r.failed_at <= 0.4);
}
