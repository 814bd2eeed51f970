// Dark breathers of a model file exist only where the background can sit (issue 27, defect 3):
// with the far-field mean strain fixed to zero the plane wave's frequency is omega + h A^2, so
// omega_b must lie on the side of the edge where (omega_b - omega) h > 0 (h, not h_tilde); the seed's
// amplitude is that plane wave's; and a converged Newton result is kept only if it is a dark breather.
// FPUT with a = -3/2, b = 7/6 has the Taylor coefficients K2, K3, K4 of the Morse chain
// (F(r) = exp(-r) - exp(-2 r) = r - 3/2 r^2 + 7/6 r^3 + ...), hence its NLS coefficients at theta = pi:
// omega = 2, h = 14, h_tilde = -22 (`lrchain coeffs --model tests/data/models/morse.toml`).
#include <doctest/doctest.h>

#include <cmath>
#include <numbers>
#include <string>

#include "lrchain/errors.hpp"
#include "lrchain/jobs/dark_job.hpp"
#include "lrchain/model.hpp"
#include "lrchain/sim/dark/dark_ansatz.hpp"
#include "lrchain/sim/dark/dark_shape.hpp"
#include "lrchain/sim/model_lattice.hpp"

using namespace lrchain;
using namespace lrchain::jobs::dark;

namespace {

struct ShippedModel {
  Model model;
  const char* name;
  DarkConfig config(DarkStep step, double omega_b, Index sites) const {
    DarkConfig c;
    c.step = step;
    c.model = &model;
    c.kernels = sim::shipped_lattice_kernels(name);
    c.omega_b = omega_b;
    c.sites = sites;
    return c;
  }
};

ShippedModel morse_like() { return {shipped_model("fput", {{"a", -1.5}, {"b", 7.0 / 6.0}}), "fput"}; }
ShippedModel klein_gordon() { return {shipped_model("klein_gordon", {{"b", -0.5}}), "klein_gordon"}; }

std::string refusal(const DarkConfig& c) {
  try {
    validate(c);
  } catch (const InvalidParameter& e) {
    return e.what();
  }
  return "";
}

}  // namespace

TEST_CASE("dark model: omega_b on the side of h, not h_tilde (the Morse coefficients h = 14, h_tilde = -22)" *
          doctest::test_suite("fast")) {
  const ShippedModel m = morse_like();
  // Below the edge (the h_tilde side main accepted, where Newton found a standing wave): refused.
  const std::string below = refusal(m.config(DarkStep::solve, 1.99, 61));
  CHECK(below.find("must lie above omega = 2") != std::string::npos);
  CHECK(below.find("h = 14") != std::string::npos);
  CHECK(below.find("h_tilde = -22 only sets the dip's width") != std::string::npos);
  // Above it the breather exists: Newton converges to a dark breather whose far-field strain is the
  // plane wave 4 A cos(omega_b t) (r = u_n - u_(n-1) of u = 2 A (-1)^n cos) with omega_b - omega = h A^2.
  const DarkConfig c = m.config(DarkStep::solve, 2.002, 61);
  validate(c);
  const DarkResult r = run(c);
  INFO(r.newton.failure);
  REQUIRE(r.newton.converged);
  const double A = std::sqrt(0.002 / 14);
  CHECK(std::abs(r.z0(0)) == doctest::Approx(4 * A).epsilon(0.02));
  CHECK(std::abs(r.z0(30)) < 0.5 * 4 * A);  // the dip at the centre n = 30 (bond n0 = 1/2 next to it)
}

TEST_CASE("dark model: the seed's amplitude is the plane wave's at omega_b (klein_gordon, on-site)" *
          doctest::test_suite("fast")) {
  // omega_b - omega = h A^2 with the carrier 2 A cos: at b = -1/2, omega = sqrt(1.4), h = -0.72803;
  // the converged far field (the seed's end sites) agrees with the seed to 2% (main's seed had
  // sqrt(3 (omega_b - omega)/h_tilde), sqrt(3) too large for an on-site model).
  const ShippedModel m = klein_gordon();
  const DarkConfig c = m.config(DarkStep::solve, 1.17, 31);
  const DarkResult r = run(c);
  REQUIRE(r.newton.converged);
  CHECK(std::abs(r.z0(0)) == doctest::Approx(std::abs(r.seed(0))).epsilon(0.02));
  CHECK(std::abs(r.seed(0)) == doctest::Approx(2 * std::sqrt((1.17 - std::sqrt(1.4)) / -0.72802689877429283)).epsilon(1e-3));
}

TEST_CASE("dark model: a converged state that is not a dark breather is recognised" * doctest::test_suite("fast")) {
  const ShippedModel m = klein_gordon();
  const Index sites = 101;
  const sim::dark::DarkAnsatz a = sim::dark::make_dark_ansatz(
      m.model, *sim::shipped_lattice_kernels("klein_gordon"), sim::dark::defocusing_edge(m.model, std::nullopt), 1.17);
  const Eigen::VectorXd seed = sim::dark::dark_seed(a, DarkCenter::bond, sites);
  CHECK(sim::dark::dark_shape_failure(a, DarkCenter::bond, sites, seed).empty());
  // The linear standing mode k = 49 of the 101-site ring (what main's Newton found for the Morse chain).
  Eigen::VectorXd standing(sites);
  for (Index i = 0; i < sites; ++i) standing(i) = 0.2 * std::cos(2 * std::numbers::pi * 49.0 * double(i) / double(sites));
  CHECK(sim::dark::dark_shape_failure(a, DarkCenter::bond, sites, standing).find("far field is not the plane wave") !=
        std::string::npos);
  // The plane wave with no dip (the seed's far field continued through the centre).
  const Eigen::VectorXd flat = std::abs(seed(0)) * seed.cwiseSign();
  CHECK(sim::dark::dark_shape_failure(a, DarkCenter::bond, sites, flat).find("no dip") != std::string::npos);
  // The same background at a tenth of the plane wave's amplitude is not the plane wave at omega_b.
  CHECK(sim::dark::dark_shape_failure(a, DarkCenter::bond, sites, seed / 10).find("not the plane wave's at omega_b") !=
        std::string::npos);
}

TEST_CASE("dark model: a theta = 0 pair with mean flow is a dark breather (resonant_chain_polynomial)" *
          doctest::test_suite("fast")) {
  // Defocusing at theta = 0 with h = h_tilde = 4.8 > 0 (lambda = 0): the pair above omega = 2
  // (docs/dark-models.md); its carrier is in w1 = v - u, the strain r has no far-field carrier.
  const ShippedModel m{shipped_model("resonant_chain_polynomial", {}), "resonant_chain_polynomial"};
  const DarkResult r = run(m.config(DarkStep::solve, 2.01, 60));
  INFO(r.newton.failure);
  CHECK(r.newton.converged);
}
