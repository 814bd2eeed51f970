// Emitting (ansatz) ends of a model bright run (ModelBrightConfig::ansatz_ends): the sites beyond
// both ends follow the NLS ansatz, so a short chain behaves as an unbounded one. The reference is
// the same breather on a chain long enough that its ends play no part over the run (fixed or
// strain-free ends, srkn11b): with ansatz ends the short chain's max E_x must equal it, while the
// short chain with its own ends cuts the breather's tails (or the breather runs into them) and its
// max E_x is many times larger.
#include <doctest/doctest.h>

#include <cmath>
#include <cstdio>
#include <numbers>

#include "lrchain/sim/bright_run.hpp"

using namespace lrchain;
using namespace lrchain::sim;

namespace {

// fput's acoustic breather at theta = pi/2 (mean flow, strain form), detuning 1e-4, from n0.
ModelBrightConfig fput_at_half_pi(const Model& fput, double n0, double periods) {
  ModelBrightConfig c;
  c.branch = fput.branch("acoustic");
  c.theta = std::numbers::pi / 2;
  c.detuning = 1e-4;
  c.n0 = n0;
  c.periods = periods;
  return c;
}

double max_E_x(const Model& model, ModelBrightConfig c, long N, bool ansatz_ends) {
  c.N = N;
  c.ansatz_ends = ansatz_ends;
  return run_bright(model, lattice_kernels_of(model), c).max_error.at(0);
}

}  // namespace

TEST_CASE("model bright: ansatz ends make a short chain match a long one (klein_gordon at rest, fput leaving the chain)" *
          doctest::test_suite("fast")) {
  {
    // klein_gordon, theta = 3 pi/4, detuning 1e-4: width 1/a = 18 sites, c = 0.061, 50 T_b. N = 60 cuts
    // the tails at 3.3 widths. Measured: long chain 0.079 %, short with ansatz ends 0.079 %, short with
    // fixed ends 15.7 %.
    const Model model = shipped_model("klein_gordon");
    ModelBrightConfig c;
    c.branch = model.branch("branch0");
    c.theta = 3 * std::numbers::pi / 4;
    c.detuning = 1e-4;
    c.periods = 50;
    const double reference = max_E_x(model, c, 500, false), fixed = max_E_x(model, c, 60, false),
                 emitting = max_E_x(model, c, 60, true);
    std::printf("klein_gordon ends: long %.5f, short fixed %.5f, short ansatz ends %.5f\n", reference, fixed, emitting);
    CHECK(std::abs(emitting - reference) < 1e-3 * reference);
    CHECK(fixed > 5 * emitting);
  }
  {
    // fput, theta = pi/2 (mean flow, strain form), detuning 1e-4: c = 0.707, so over 50 T_b the breather
    // moves 157 sites and leaves the chain n = -100..100 through its right end. Measured: long chain
    // (N = 1000) 0.015 %, short with ansatz ends 0.015 %, short with strain-free ends 117 %.
    const Model model = shipped_model("fput");
    const ModelBrightConfig c = fput_at_half_pi(model, -40, 50);
    const double reference = max_E_x(model, c, 1000, false), fixed = max_E_x(model, c, 100, false),
                 emitting = max_E_x(model, c, 100, true);
    std::printf("fput ends: long %.5f, short fixed %.5f, short ansatz ends %.5f\n", reference, fixed, emitting);
    CHECK(std::abs(emitting - reference) < 0.02 * reference);
    CHECK(fixed > 50 * emitting);
  }
}

TEST_CASE("model bright: a breather that runs into a fixed end is reported, one that stays inside is not" *
          doctest::test_suite("fast")) {
  // fput, theta = pi/2, detuning 1e-4: c = cos(pi/4) = 0.7071 (the textbook monatomic chain), width
  // 1/a = 42 sites (a = 0.02378, the run's inverse_width), T_b = 4.443.
  const Model model = shipped_model("fput");
  // 201 sites, n0 = -40: the left end is 1.4 widths away.
  ModelBrightConfig c = fput_at_half_pi(model, -40, 10);
  c.N = 100;
  const ModelBrightResult short_chain = run_bright(model, lattice_kernels_of(model), c);
  CHECK(short_chain.end_zone == 10);  // 201 sites / 20
  REQUIRE(short_chain.end_reached_at.has_value());
  CHECK(*short_chain.end_reached_at == 0);
  // The sech^2 envelope cut at the ends n = -100, 100 puts (tanh(60 a) - tanh(50 a))/(tanh(60 a) +
  // tanh(140 a)) = 0.032 of the energy in n = -100..-90 at t = 0 (measured max 0.037).
  const double a = short_chain.inverse_width;
  const double cut_envelope = (std::tanh(60 * a) - std::tanh(50 * a)) / (std::tanh(60 * a) + std::tanh(140 * a));
  CHECK(std::abs(*short_chain.max_end_energy_fraction / cut_envelope - 1) < 0.2);  // relative
  // 601 sites, n0 = 0: the energy envelope sech^2(a (n - c t)) puts 1 % beyond n = 270 (the end zone)
  // when a (270 - c t) = atanh(0.98) = 2.298, at t = (270 - 2.298/a)/c = 245.3. Measured 248.8.
  c.n0 = 0;
  c.N = 300;
  c.periods = 80;
  const ModelBrightResult runs_out = run_bright(model, lattice_kernels_of(model), c);
  REQUIRE(runs_out.end_reached_at.has_value());
  const double predicted = (270 - std::atanh(0.98) / runs_out.inverse_width) / runs_out.group_velocity;
  CHECK(*runs_out.end_reached_at == doctest::Approx(predicted).epsilon(0.05));
  // Over 40 T_b the same breather stays 2.9 widths from the zone: below 1 % (measured 0.096 %).
  c.periods = 40;
  const ModelBrightResult stays = run_bright(model, lattice_kernels_of(model), c);
  CHECK_FALSE(stays.end_reached_at.has_value());
  CHECK(*stays.max_end_energy_fraction < 0.01);
  CHECK(*stays.max_end_energy_fraction > 1e-4);
}
