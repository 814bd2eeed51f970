// `dark evolve --perturb` (issue 27): an instability can be watched. Along the eigenvector of the
// largest Floquet multiplier lambda the distance from the breather grows like |lambda|^m over m
// periods (the linearisation's own growth, while it stays small); a random perturbation is
// reproducible from its seed.
#include <doctest/doctest.h>

#include <cmath>

#include "lrchain/errors.hpp"
#include "lrchain/jobs/dark_job.hpp"
#include "lrchain/model.hpp"
#include "lrchain/sim/model_lattice.hpp"

using namespace lrchain;
using namespace lrchain::jobs::dark;

namespace {
DarkConfig evolve_config(const Model& model, const std::string& perturb, double omega_b = 1.586) {
  DarkConfig c;
  c.step = DarkStep::evolve;
  c.model = &model;
  c.kernels = sim::shipped_lattice_kernels("klein_gordon");
  // klein_gordon (C = 1/2 in the unstable cases): real instability at omega_b = 1.586 (dark continue's Floquet
  // multipliers: max |lambda| = 1.0724 at 1.5861 on 61 sites).
  c.omega_b = omega_b;
  c.sites = 31;
  c.t_end = 60;  // 15 periods of T_b = 3.96
  c.perturb = perturb;
  c.perturb_size = 1e-6;
  validate(c);
  return c;
}
}  // namespace

TEST_CASE("dark evolve --perturb unstable: the distance from the breather grows like |lambda|^m" *
          doctest::test_suite("fast")) {
  const Model model = shipped_model("klein_gordon", {{"b", -0.5}, {"C", 0.5}});
  const DarkResult r = run(evolve_config(model, "unstable"));
  REQUIRE_FALSE(failure(r).has_value());
  const double lambda = std::abs(r.perturbation.multiplier);
  CHECK(lambda == doctest::Approx(1.0713).epsilon(2e-3));  // measured on these 31 sites
  CHECK(std::abs(r.perturbation.multiplier.imag()) < 1e-9);
  CHECK(r.perturbation.vector.cwiseAbs().maxCoeff() == doctest::Approx(1e-6));
  const auto& periods = r.evolution.periods;
  REQUIRE(periods.size() == 15);
  for (std::size_t m = 4; m < periods.size(); m += 5) {
    const double growth = periods[m].E_b / periods[0].E_b;
    INFO("period " << m + 1 << ": E_b grew by " << growth << ", lambda^" << m << " = " << std::pow(lambda, double(m)));
    // The component along the other multipliers (all on the unit circle) stays ~1e-6: within 5 %.
    CHECK(growth == doctest::Approx(std::pow(lambda, double(m))).epsilon(0.05));
  }
}

TEST_CASE("dark evolve --perturb random: the seed fixes the perturbation, size its max-norm" *
          doctest::test_suite("fast")) {
  const Model model = shipped_model("klein_gordon", {{"b", -0.5}, {"C", 0.5}});
  DarkConfig c = evolve_config(model, "random");
  c.t_end = 8;  // two periods
  c.seed = 7;
  const DarkResult a = run(c), b = run(c);
  c.seed = 8;
  const DarkResult other = run(c);
  REQUIRE(a.perturbation.vector.size() == 2 * 31);
  CHECK(a.perturbation.vector == b.perturbation.vector);
  CHECK((a.perturbation.vector - other.perturbation.vector).cwiseAbs().maxCoeff() > 1e-7);
  CHECK(a.perturbation.vector.head(31).cwiseAbs().maxCoeff() <= 1e-6);
  CHECK(a.perturbation.vector.head(31).cwiseAbs().maxCoeff() > 0.5e-6);
  CHECK(a.perturbation.vector.tail(31).isZero());  // velocities unperturbed
  CHECK(a.evolution.snapshots.front() == a.z0 + a.perturbation.vector.head(31));
  CHECK(to_json(a)["perturbation"]["seed"] == 7);
  // The seed's range is Python's, [0, 2^31): a CLI's --seed -1 arrives as 2^64 - 1 and is refused.
  c.seed = std::uint64_t(-1);
  try {
    validate(c);
    FAIL("seed 2^64 - 1 was accepted");
  } catch (const InvalidParameter& e) {
    CHECK(e.parameter() == "seed");
  }
}

TEST_CASE("dark evolve --perturb unstable on a stable breather: refused naming perturb" * doctest::test_suite("fast")) {
  // klein_gordon, b = -1/2 (C = 1/10, its default) at omega_b = 1.17: Floquet stable (docs/dark-models.md,
  // max|lambda| = 1.0002 from the symmetry multipliers at +1), so no multiplier gives a direction that grows.
  const Model model = shipped_model("klein_gordon", {{"b", -0.5}});
  DarkConfig c = evolve_config(model, "unstable", 1.17);
  c.t_end = 10;
  validate(c);  // a valid Config: the refusal needs the solved breather's multipliers
  try {
    (void)run(c);
    FAIL("perturb unstable ran on a stable breather");
  } catch (const InvalidParameter& e) {
    CHECK(e.parameter() == "perturb");
    CHECK(std::string(e.what()).find("use perturb random") != std::string::npos);
  }
  c.perturb = "random";  // the same breather with a random perturbation runs
  CHECK_FALSE(failure(run(c)).has_value());
}
