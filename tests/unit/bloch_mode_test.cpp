// The Bloch modes of a lattice from its generated kernels (sim/model_lattice_bloch.hpp) where one
// branch's first field is at rest: the diatomic chain (masses 1 and m = 2) at theta = pi, whose
// acoustic mode moves only the heavy beads and whose optical mode only the light ones (a textbook
// result: Kittel, Introduction to Solid State Physics, Ch. 4, omega^2 = 2 K2/m and 2 K2/1 at the zone
// boundary). Only a job on the acoustic branch there is refused; the optical edge, the lower edge of
// the gap where gap breathers live, is usable.
#include <doctest/doctest.h>

#include <cmath>
#include <numbers>
#include <string>

#include "lrchain/errors.hpp"
#include "lrchain/model.hpp"
#include "lrchain/sim/bright/bright_seed.hpp"
#include "lrchain/sim/model_lattice.hpp"
#include "lrchain/sim/model_lattice_bloch.hpp"

using namespace lrchain;

TEST_CASE("Bloch modes: a branch whose first field is at rest is refused alone (diatomic chain at theta = pi)" *
          doctest::test_suite("fast")) {
  const Model diatomic = shipped_model("diatomic_chain");  // m = 2, K2 = 1
  const lrchain_lattice_kernels& kernels = sim::lattice_kernels_of(diatomic);
  const double pi = std::numbers::pi;
  const auto modes = sim::bloch_modes(kernels, sim::lattice_parameters(diatomic), pi);
  REQUIRE(modes.size() == 2);
  CHECK(modes[0].omega == doctest::Approx(1.0).epsilon(1e-12));            // sqrt(2 K2 / m)
  CHECK(modes[1].omega == doctest::Approx(std::sqrt(2.0)).epsilon(1e-12));  // sqrt(2 K2 / 1)
  CHECK(modes[0].kernel.empty());  // the light bead (the first field) is at rest in the acoustic mode
  REQUIRE(modes[1].kernel.size() == 2);
  CHECK(std::abs(modes[1].kernel[1]) < 1e-10);  // and the heavy bead in the optical mode

  try {
    sim::bloch_mode(diatomic, kernels, 0, pi);
    FAIL("the acoustic mode at theta = pi was accepted");
  } catch (const InvalidParameter& e) {
    CHECK(e.parameter() == "theta");
    CHECK(std::string(e.what()).find("branch acoustic") != std::string::npos);
  }
  CHECK(sim::bloch_mode(diatomic, kernels, 1, pi).omega == doctest::Approx(std::sqrt(2.0)).epsilon(1e-12));

  // A gap breather below the optical edge: the edge is found (the acoustic one at pi is not in the way).
  const sim::bright::FocusingEdge edge = sim::bright::focusing_edge(diatomic, Index(1), std::sqrt(2.0) - 0.01);
  CHECK(edge.branch == 1);
  CHECK(edge.theta == doctest::Approx(pi));
  CHECK(edge.nls.h_tilde < 0);  // breathers below the edge: in the gap (1, sqrt 2)
}
