// `dark continue --model` follows a branch (issue 27, continuation): the reflection family is imposed
// (lattice_reflection.hpp), so steps cannot slide along the translation mode; the arclength weighs the
// state against omega_b, so N points move omega_b by about N ds; folds are located. Before (main
// 0a5fc88), klein_gordon at C = 1/2 crept 2.7e-7 in omega_b per point with norm^2 wandering, and
// newtons_cradle stopped at omega_b = 2.219999 (step below 1e-5).
#include <doctest/doctest.h>

#include <cmath>

#include "lrchain/errors.hpp"
#include "lrchain/jobs/dark_job.hpp"
#include "lrchain/model.hpp"
#include "lrchain/sim/model_lattice.hpp"

using namespace lrchain;
using namespace lrchain::jobs::dark;

namespace {
DarkResult continue_model(const Model& model, const char* name, double omega_b, Index sites, Index points, double ds) {
  DarkConfig c;
  c.step = DarkStep::branch;
  c.model = &model;
  c.kernels = sim::shipped_lattice_kernels(name);
  c.omega_b = omega_b;
  c.sites = sites;
  c.points = points;
  c.ds = ds;
  c.branch_floquet = false;
  validate(c);
  return run(c);
}
}  // namespace

TEST_CASE("dark continue --model: klein_gordon at C = 1/2 moves omega_b by about ds per point, norm^2 monotone" *
          doctest::test_suite("fast")) {
  const Model model = shipped_model("klein_gordon", {{"b", -0.5}, {"C", 0.5}});
  const double ds = 0.002;
  const DarkResult r = continue_model(model, "klein_gordon", 1.72, 31, 6, ds);
  REQUIRE_FALSE(failure(r).has_value());
  CHECK(r.symmetry.find("at all times") != std::string::npos);  // the bond-centred breather is R-even
  const auto& points = r.branch.points;
  REQUIRE(points.size() == 6);
  // The first step: the state's part weighs as much as omega_b's, so d omega_b = ds/sqrt(2) to first
  // order in ds (continuation.hpp); the step grows by 1.5 at most per easy point after that.
  CHECK(points[0].omega_b - points[1].omega_b == doctest::Approx(ds / std::sqrt(2.0)).epsilon(0.1));
  for (std::size_t i = 1; i < points.size(); ++i) {
    INFO("point " << i << ": omega_b = " << points[i].omega_b << ", norm^2 = " << points[i].measures.norm_squared);
    const double step = points[i - 1].omega_b - points[i].omega_b;
    CHECK(step > 0.5 * ds / std::sqrt(2.0));
    CHECK(step <= ds * std::pow(1.5, double(i - 1)));  // never more than the arclength step
    // Along this part of the branch the dip deepens as omega_b falls (measured 0.9138 -> 1.0); a step
    // along the translation mode would change norm^2 at fixed omega_b instead.
    CHECK(points[i].measures.norm_squared > points[i - 1].measures.norm_squared);
    CHECK(points[i].measures.E_b < 1e-9);
  }
}

TEST_CASE("dark continue --model: newtons_cradle passes omega_b = 2.22 and its fold is located" *
          doctest::test_suite("fast")) {
  const Model model = shipped_model("newtons_cradle", {});
  const DarkResult r = continue_model(model, "newtons_cradle", 2.22, 41, 9, 0.01);
  REQUIRE_FALSE(failure(r).has_value());
  const auto& points = r.branch.points;
  REQUIRE(points.size() == 9);
  CHECK(points[2].omega_b < 2.21);
  CHECK(r.symmetry.find("after half a period") != std::string::npos);
  // The branch turns at omega_b ~ 2.1198 (41 sites; measured) and climbs back: one fold between the
  // lowest points, at or below the lowest point's omega_b. A run with ds = 0.002 (16 points)
  // locates it at 2.1197999, this one at 2.1198240: agreement to 1e-4 (the Hermite interpolant's error).
  REQUIRE(r.branch.folds.size() == 1);
  const auto& fold = r.branch.folds.front();
  double lowest = points.front().omega_b;
  for (const auto& p : points) lowest = std::min(lowest, p.omega_b);
  CHECK(fold.omega_b <= lowest + 1e-9);
  CHECK(fold.omega_b == doctest::Approx(2.1198).epsilon(5e-5));
  CHECK(r.branch.turning_points.size() == 1);
  const auto& before = points[std::size_t(fold.after)], &after = points[std::size_t(fold.after) + 1];
  CHECK(before.tangent_omega < 0);
  CHECK(after.tangent_omega > 0);
  CHECK(fold.norm_squared > before.measures.norm_squared);
  CHECK(fold.norm_squared < after.measures.norm_squared);
}

TEST_CASE("dark continue --model: fput (b = -1/2), a strain lattice, moves off its edge" * doctest::test_suite("fast")) {
  const Model model = shipped_model("fput", {{"b", -0.5}});
  const double ds = 0.01;
  const DarkResult r = continue_model(model, "fput", 1.99, 41, 5, ds);
  REQUIRE_FALSE(failure(r).has_value());
  CHECK_FALSE(r.symmetry.empty());
  const auto& points = r.branch.points;
  REQUIRE(points.size() == 5);
  // 4 steps of at least ds/(2 sqrt 2) each (measured: 1.99 -> 1.9471 in 4 points).
  CHECK(points.front().omega_b - points.back().omega_b > 4 * 0.5 * ds / std::sqrt(2.0));
  for (std::size_t i = 1; i < points.size(); ++i) {
    CHECK(points[i].omega_b < points[i - 1].omega_b);
    CHECK(points[i].measures.E_b < 1e-9);
  }
}

TEST_CASE("dark continue --model: a theta = 0 pair with mean flow is continued in its reflection family" *
          doctest::test_suite("fast")) {
  // resonant_chain_polynomial's optical branch is defocusing at theta = 0 (docs/dark-models.md): a pair
  // of dips on 60 sites. Its seed is symmetric only up to the tails the ring's closure changes, so the
  // reflection is read off the solved breather (symmetric to 2.4e-6 of its peak, measured); without a
  // family the steps slid along the translation direction and stopped after 2 points (step_too_small
  // at omega_b = 2.010035). Measured with the family: 2.01, 2.0305, 2.0530, 2.0880, 2.1418, ...
  const Model model = shipped_model("resonant_chain_polynomial");
  const DarkResult r = continue_model(model, "resonant_chain_polynomial", 2.01, 60, 6, 0.1);
  REQUIRE_FALSE(failure(r).has_value());
  CHECK(r.symmetry == "i -> (32 - i) mod 60 with sign +; i -> (31 - i) mod 60 with sign -, at all times");
  const auto& points = r.branch.points;
  REQUIRE(points.size() == 6);
  // Away from the edge omega = 2 (measured 2.01 -> 2.1799 in five steps; without the family the branch
  // stalled 3.5e-5 from its start).
  CHECK(points.back().omega_b - points.front().omega_b > 0.1);
  for (std::size_t i = 1; i < points.size(); ++i) {
    CHECK(points[i].omega_b > points[i - 1].omega_b);
    CHECK(points[i].measures.E_b < 1e-9);
  }
}

TEST_CASE("dark continue --to narrows the window: beyond the band edge or outside omega_min is refused naming to" *
          doctest::test_suite("fast")) {
  // klein_gordon at C = 1/2: the breather at 1.72 lies below the top of the phonon band, sqrt(1 + 4 C) =
  // sqrt(3) = 1.7321 (the textbook Klein-Gordon band), and continues down from it. Before, --to 1.75
  // replaced the bound at the edge and the branch ran through the linear limit, reporting a fold there.
  const Model model = shipped_model("klein_gordon", {{"b", -0.5}, {"C", 0.5}});
  DarkConfig c;
  c.step = DarkStep::branch;
  c.model = &model;
  c.kernels = sim::shipped_lattice_kernels("klein_gordon");
  c.omega_b = 1.72;
  c.sites = 31;
  c.points = 3;
  c.branch_floquet = false;
  c.to = 1.75;
  validate(c);
  CHECK_THROWS_WITH_AS(run(c), doctest::Contains("band edge 1.732050808"), InvalidParameter);
  c.to = 1.69;  // below a user's omega_min
  c.omega_min = 1.70;
  validate(c);
  CHECK_THROWS_WITH_AS(run(c), doctest::Contains("must lie in [1.7,"), InvalidParameter);
  c.to = 1.71;  // inside: the last point lands on it
  const DarkResult r = run(c);
  REQUIRE_FALSE(failure(r).has_value());
  CHECK(r.branch.points.back().omega_b == doctest::Approx(1.71).epsilon(1e-12));
}
