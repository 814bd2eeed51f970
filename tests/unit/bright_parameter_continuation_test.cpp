// `bright continue --parameter C --to X` through the library (lrchain/jobs/bright_breather_job.hpp):
// a Klein-Gordon breather continued in its coupling C towards the anti-continuum limit ends on the
// one-oscillator solution (MacKay & Aubry, Nonlinearity 7, 1623 (1994)) and on the breather Newton
// finds there directly from the NLS seed.
#include <doctest/doctest.h>

#include <cmath>
#include <numbers>
#include <string>

#include <boost/math/quadrature/gauss_kronrod.hpp>
#include <boost/math/tools/roots.hpp>

#include "../support/oscillator_amplitude.hpp"
#include "lrchain/errors.hpp"
#include "lrchain/jobs/bright_breather_job.hpp"
#include "lrchain/model.hpp"
#include "lrchain/sim/model_lattice.hpp"

using namespace lrchain;
using namespace lrchain::jobs::bright_breather;

namespace {

BrightBreatherConfig kg_config(const Model& model, BrightStep step) {
  BrightBreatherConfig c;
  c.step = step;
  c.model = &model;
  c.kernels = sim::shipped_lattice_kernels("klein_gordon");
  c.omega_b = 1.1;
  c.sites = 21;
  return c;
}

}  // namespace

TEST_CASE("bright continue in C: the Klein-Gordon breather tends to one oscillator as C -> 0" * doctest::test_suite("fast")) {
  const Model model = shipped_model("klein_gordon", {{"C", 0.01}, {"a", 0.0}});
  BrightBreatherConfig c = kg_config(model, BrightStep::branch);
  c.parameter = "C";
  c.to = 0.001;
  c.points = 40;
  validate(c);
  const BrightBreatherResult r = run(c);
  INFO(failure(r).value_or(""), " ", r.branch.stop_reason);
  REQUIRE(!failure(r));
  REQUIRE(r.branch.points.size() >= 2);
  const auto& last = r.branch.points.back();
  MESSAGE(r.branch.points.size(), " points, last C = ", last.parameter, " peak ", r.branch_profiles.back().peak);
  CHECK(last.parameter == doctest::Approx(0.001).epsilon(1e-12));  // landed on --to
  CHECK(last.omega_b == 1.1);                                    // at fixed omega_b
  // Along the branch C falls monotonically and the centre's amplitude approaches the single
  // oscillator's A = 0.751 (x'' + x + x^3/2 = 0 at omega 1.1) within O(C): the coupling adds 2 C to the
  // centre's linear stiffness (its neighbours are O(C)), and with the Duffing estimate omega^2 = k +
  // 3 A^2 / 8 that lowers A by C / (omega^2 - 1) = 4.8 C relative; measured 5.18 C at C = 0.01 (the
  // O(C^2) terms and the estimate's error); allowed |peak - A| / A < 6 C.
  const double A = lrchain::test::oscillator_amplitude(1.0, 0.5, 1.1);
  for (std::size_t k = 0; k < r.branch.points.size(); ++k)
    CHECK(std::abs(r.branch_profiles[k].peak - A) / A < 6 * r.branch.points[k].parameter);
  // The continued breather at C = 0.001 is the one Newton finds there from the NLS seed (the same
  // zero of the shooting map, reached by another path): equal to the Newton tolerance.
  const Model at_end = shipped_model("klein_gordon", {{"C", 0.001}, {"a", 0.0}});
  const BrightBreatherConfig direct = kg_config(at_end, BrightStep::solve);
  validate(direct);
  const BrightBreatherResult d = run(direct);
  REQUIRE(!failure(d));
  CHECK((d.z0 - last.z0).cwiseAbs().maxCoeff() < 1e-9);
  // The continued parameter heads the columns of the summary's points.
  CHECK(to_json(r)["branch"]["branch_points"].back()["C"].get<double>() == doctest::Approx(0.001));
  CHECK(to_json(r)["branch"]["parameter"] == "C");
}

TEST_CASE("bright continue: validate refuses an unknown parameter, a missing or out-of-range to" * doctest::test_suite("fast")) {
  const Model model = shipped_model("klein_gordon", {{"C", 0.01}, {"a", 0.0}});
  BrightBreatherConfig c = kg_config(model, BrightStep::branch);
  const auto key = [](const BrightBreatherConfig& config) -> std::string {
    try {
      validate(config);
    } catch (const InvalidParameter& e) {
      return e.parameter();
    }
    return "";
  };
  c.parameter = "kappa";
  c.to = 0.5;
  CHECK(key(c) == "parameter");
  c.parameter = "C";
  c.to.reset();
  CHECK(key(c) == "to");
  c.to = 0.01;  // its present value
  CHECK(key(c) == "to");
  c.parameter = "omega_b";
  c.to = 1.0;  // inside the band
  CHECK(key(c) == "to");
  c.to = 1.2;
  CHECK(key(c) == "");
}
