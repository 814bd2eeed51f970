// A second method for the Floquet-Bloch growth rates (sim/wave/wave_stability.hpp): the exact wave of the
// Klein-Gordon chain at theta = 3 pi/4 on a ring of 64 sites (theta and every K = 2 pi j/64 are modes of
// the ring) plus noise of size 1e-9, integrated directly (Boost.Odeint RK4 on the model's generated
// lattice). Its deviation from the exact wave U(theta n - omega t) grows at the largest rate over the
// ring's K; the measured slope of its log must equal the computed rate within 5 %.
#include <doctest/doctest.h>

#include <boost/numeric/odeint.hpp>
#include <cmath>
#include <numbers>
#include <random>

#include "lrchain/model.hpp"
#include "lrchain/sim/model_lattice.hpp"
#include "lrchain/sim/model_lattice_bloch.hpp"
#include "lrchain/sim/wave/travelling_wave.hpp"
#include "lrchain/sim/wave/wave_stability.hpp"

using namespace lrchain;
using namespace lrchain::sim;
using namespace lrchain::sim::wave;


TEST_CASE("wave stability: a ring run of the exact wave plus noise grows at the computed rate" * doctest::test_suite("fast")) {
  const Model model = shipped_model("klein_gordon");
  const lrchain_lattice_kernels& kernels = lattice_kernels_of(model);
  const double theta = 3 * std::numbers::pi / 4, U = 0.2;
  const Index sites = 64;
  const BlochMode mode = bloch_mode(model, kernels, 0, theta);
  WaveLattice lattice(kernels, lattice_parameters(model), theta);
  const WaveBranch branch = continue_travelling_wave(lattice, mode, {0.05, 0.1, 0.15, U});
  REQUIRE(!branch.stopped);
  const TravellingWave& w = branch.waves.back();
  BlochSpectrum spectrum(lattice, w);
  double computed = 0;
  for (Index j = 1; j <= sites / 2; ++j)
    if (j % 8 != 0) computed = std::max(computed, spectrum.growth_rate(2 * std::numbers::pi * double(j) / double(sites)));
  REQUIRE(computed > 1e-3);

  const auto c = wave_harmonics(w, 0);
  const CompiledLattice ring(kernels, lattice_parameters(model), sites, true, LatticeForm::displacement);
  State s(2 * std::size_t(sites));
  std::mt19937 gen(7);
  std::normal_distribution<double> noise(0, 1e-9);
  for (Index n = 0; n < sites; ++n) {
    double u, du;
    profile_at(c, theta * double(n), u, du);
    s[std::size_t(n)] = u + noise(gen);
    s[std::size_t(sites + n)] = -w.omega * du;  // d/dt U(theta n - omega t)
  }
  // The deviation from the exact wave in the ring's modes j that are no harmonic of the wave (j not a
  // multiple of 8: theta = 2 pi 24/64), where the neutral phase and amplitude changes of the wave do not
  // show: its largest mode amplitude, sampled every carrier period, its log fitted against t where it is
  // between 1e-6 and 1e-3 (after the noise has settled onto the fastest mode, before saturation).
  const auto sideband = [&](const State& x, double t) {
    std::vector<double> d(static_cast<std::size_t>(sites));
    for (Index n = 0; n < sites; ++n) {
      double u, du;
      profile_at(c, theta * double(n) - w.omega * t, u, du);
      d[std::size_t(n)] = x[std::size_t(n)] - u;
    }
    double largest = 0;
    for (Index j = 1; j < sites; ++j) {
      if (j % 8 == 0) continue;
      std::complex<double> a = 0;
      for (Index n = 0; n < sites; ++n) a += d[std::size_t(n)] * std::polar(1.0, -2 * std::numbers::pi * double(j * n) / double(sites));
      largest = std::max(largest, std::abs(a) / double(sites));
    }
    return largest;
  };
  boost::numeric::odeint::runge_kutta4<State> stepper;
  const double period = 2 * std::numbers::pi / w.omega, dt = period / 100;
  std::vector<double> ts, logs;
  double t = 0;
  for (int p = 0; p < 4000; ++p) {
    for (int i = 0; i < 100; ++i, t += dt) stepper.do_step(std::cref(ring), s, t, dt);
    const double d = sideband(s, t);
    if (d > 1e-3) break;
    if (d > 1e-6) {
      ts.push_back(t);
      logs.push_back(std::log(d));
    }
  }
  REQUIRE(ts.size() > 20);
  double mt = 0, ml = 0;
  for (std::size_t i = 0; i < ts.size(); ++i) mt += ts[i], ml += logs[i];
  mt /= double(ts.size());
  ml /= double(ts.size());
  double sxy = 0, sxx = 0;
  for (std::size_t i = 0; i < ts.size(); ++i) sxy += (ts[i] - mt) * (logs[i] - ml), sxx += (ts[i] - mt) * (ts[i] - mt);
  const double measured = sxy / sxx;
  MESSAGE("ring growth: measured " << measured << ", Floquet-Bloch " << computed << " over " << ts.size() << " periods");
  CHECK(std::abs(measured / computed - 1) < 0.05);
}
