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

#include "lrchain/sim/model_bright_run.hpp"

using namespace lrchain;
using namespace lrchain::sim;

namespace {

double max_E_x(const Model& model, ModelBrightConfig c, long N, bool ansatz_ends) {
  c.N = N;
  c.ansatz_ends = ansatz_ends;
  return run_model_bright(model, lattice_kernels_of(model), c).max_error.at(0);
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
    ModelBrightConfig c;
    c.branch = model.branch("acoustic");
    c.theta = std::numbers::pi / 2;
    c.detuning = 1e-4;
    c.n0 = -40;
    c.periods = 50;
    const double reference = max_E_x(model, c, 1000, false), fixed = max_E_x(model, c, 100, false),
                 emitting = max_E_x(model, c, 100, true);
    std::printf("fput ends: long %.5f, short fixed %.5f, short ansatz ends %.5f\n", reference, fixed, emitting);
    CHECK(std::abs(emitting - reference) < 0.02 * reference);
    CHECK(fixed > 50 * emitting);
  }
}
