// `dark continue --model` moves along the branch (issue 27, continuation): from omega_b = 1.17 below
// the theta = pi edge of klein_gordon (b = -1/2; omega = sqrt(1.4), h = -0.728,
// docs/dark-models.md) the points step away from the edge, and the far-field amplitude K_x follows
// the plane wave's 2 A, A = sqrt((omega_b - omega)/h) (the carrier 2 A cos(omega_b t)), to O(A^2).
#include <doctest/doctest.h>

#include <cmath>

#include "lrchain/jobs/dark_job.hpp"
#include "lrchain/model.hpp"
#include "lrchain/sim/model_lattice.hpp"

using namespace lrchain;
using namespace lrchain::jobs::dark;

TEST_CASE("dark continue --model: klein_gordon's branch leaves the edge, its far field the plane wave's 2 A" *
          doctest::test_suite("fast")) {
  const Model model = shipped_model("klein_gordon", {{"b", -0.5}});
  DarkConfig c;
  c.step = DarkStep::branch;
  c.model = &model;
  c.kernels = sim::shipped_lattice_kernels("klein_gordon");
  c.omega_b = 1.17;
  c.sites = 31;
  c.points = 8;
  c.branch_floquet = false;
  validate(c);
  const DarkResult r = run(c);
  REQUIRE_FALSE(failure(r).has_value());
  const auto& points = r.branch.points;
  REQUIRE(points.size() == 8);
  const double omega = r.edge.omega, h = -0.728;  // h of the docs' example, 3 digits
  CHECK(omega == doctest::Approx(std::sqrt(1.4)).epsilon(1e-12));
  for (std::size_t i = 1; i < points.size(); ++i) CHECK(points[i].omega_b < points[i - 1].omega_b);
  // Measured: 8 points from 1.17 reach 1.1647 (ds 0.1, growing by 1.5 after easy corrections).
  CHECK(points.back().omega_b < 1.168);
  for (const auto& p : points) {
    const double a_squared = (p.omega_b - omega) / h;
    const double plane_wave = 2.0 * std::sqrt(a_squared);
    INFO("omega_b = " << p.omega_b << ", K_x = " << p.measures.K_x << ", 2 A = " << plane_wave);
    // The next order of the expansion is relative O(A^2) (measured: 0.8 % at A^2 = 0.018).
    CHECK(std::abs(p.measures.K_x / plane_wave - 1.0) < a_squared);
    CHECK(p.measures.E_b < 1e-10);
  }
}
