// The matrix-free path of the exact-breather jobs (lrchain/jobs/breather_solver.hpp: Newton-Krylov,
// sim/dark/newton_krylov.hpp; Arnoldi Floquet, sim/dark/krylov_floquet.hpp, for dark breathers; the
// windowed, certified Floquet of sim/bright/windowed_floquet.hpp for bright ones) against the dense
// path on lattices where both run: the same breather to 1e-10 and the multipliers among the dense
// monodromy's eigenvalues to 1e-8, for bright and dark breathers, on-site and strain-form models.
#include <doctest/doctest.h>

#include <algorithm>
#include <complex>
#include <limits>
#include <string>
#include <vector>

#include "lrchain/errors.hpp"
#include "lrchain/jobs/bright_breather_job.hpp"
#include "lrchain/jobs/dark_job.hpp"
#include "lrchain/model.hpp"
#include "lrchain/sim/model_lattice.hpp"

using namespace lrchain;

namespace {

// max |a - b| / max |a|: the two solutions' difference relative to the breather's peak.
double relative_difference(const Eigen::VectorXd& a, const Eigen::VectorXd& b) {
  return (a - b).lpNorm<Eigen::Infinity>() / a.lpNorm<Eigen::Infinity>();
}

// The largest distance from a Krylov multiplier to the nearest eigenvalue of the dense monodromy, the
// trivial ones within 1e-3 of +1 left out: they form Jordan blocks (phase and frequency; total strain),
// whose eigenvalues round-off moves by O(sqrt(1e-16)) in either method.
double distance_to_dense(const std::vector<std::complex<double>>& leading, const std::vector<std::complex<double>>& all) {
  double worst = 0;
  for (const auto& l : leading) {
    if (std::abs(l - 1.0) <= 1e-3) continue;
    double nearest = std::numeric_limits<double>::infinity();
    for (const auto& d : all) nearest = std::min(nearest, std::abs(l - d));
    worst = std::max(worst, nearest);
  }
  return worst;
}

// The certified multipliers of a windowed Floquet result.
std::vector<std::complex<double>> certified_multipliers(const sim::bright::WindowedFloquet& w) {
  std::vector<std::complex<double>> values;
  for (const auto& m : w.localized)
    if (m.certified) values.push_back(m.lambda);
  return values;
}

// The bright job on `name` run dense and matrix-free; `step` solve or floquet.
struct BrightPair {
  jobs::bright_breather::BrightBreatherResult dense, krylov;
};

BrightPair bright_pair(const char* name, const std::vector<std::pair<std::string, double>>& values, double omega_b,
                       Index sites, const char* center, jobs::bright_breather::BrightStep step) {
  const Model model = shipped_model(name, values);
  jobs::bright_breather::BrightBreatherConfig c;
  c.step = step;
  c.model = &model;
  c.kernels = sim::shipped_lattice_kernels(name);
  c.omega_b = omega_b;
  c.sites = sites;
  c.center = center;
  c.krylov.floquet_count = 12;
  BrightPair p;
  c.krylov.solver = "dense";
  jobs::bright_breather::validate(c);
  p.dense = jobs::bright_breather::run(c);
  c.krylov.solver = "krylov";
  jobs::bright_breather::validate(c);
  p.krylov = jobs::bright_breather::run(c);
  REQUIRE(!jobs::bright_breather::failure(p.dense));
  REQUIRE(!jobs::bright_breather::failure(p.krylov));
  return p;
}

}  // namespace

TEST_CASE("newton-krylov: a klein_gordon bright breather as the dense Newton's, its leading multipliers among the dense ones" *
          doctest::test_suite("fast")) {
  // docs/bright-breathers.md's stable Klein-Gordon breather (omega_b = 1.19 above the band), 101 sites.
  const BrightPair p = bright_pair("klein_gordon", {}, 1.19, 101, "site", jobs::bright_breather::BrightStep::floquet);
  REQUIRE(p.krylov.krylov);
  CHECK(!p.dense.krylov);
  CHECK(relative_difference(p.dense.z0, p.krylov.z0) <= 1e-10);
  // GMRES on the band-probed preconditioner: a few iterations per Newton step.
  for (Index it : p.krylov.krylov->newton.gmres_iterations) CHECK(it <= 10);
  REQUIRE(p.krylov.krylov->windowed);
  const auto& w = *p.krylov.krylov->windowed;
  REQUIRE(w.localized.size() == 12);  // the 12 asked, all certified (residual <= 1e-8)
  for (const auto& m : w.localized) CHECK(m.certified);
  REQUIRE(w.verdict);
  CHECK(w.verdict->kind() == "stable");
  REQUIRE(p.dense.floquet);
  CHECK(p.dense.floquet->stable);
  CHECK(distance_to_dense(certified_multipliers(w), p.dense.floquet->multipliers.multipliers) <= 1e-8);
}

TEST_CASE("newton-krylov: an unstable FPU breather's largest multiplier as the dense one" * doctest::test_suite("fast")) {
  // The FPU chain's bond-centred (Page) mode at a = 0 is stable and the site-centred (Sievers-Takeno) one
  // unstable (bright_breather_job_test.cpp); a strain-form model (the C_x row replaces row 0).
  const BrightPair p = bright_pair("fput", {{"a", 0.0}}, 2.2, 101, "site", jobs::bright_breather::BrightStep::floquet);
  CHECK(relative_difference(p.dense.z0, p.krylov.z0) <= 1e-10);
  REQUIRE(p.krylov.krylov->windowed);
  const auto leading = certified_multipliers(*p.krylov.krylov->windowed);
  REQUIRE(!leading.empty());
  REQUIRE(p.krylov.krylov->windowed->verdict);
  CHECK(p.krylov.krylov->windowed->verdict->kind() == "real");
  const auto& all = p.dense.floquet->multipliers.multipliers;  // |lambda| descending
  CHECK(all.front().real() > 1.0 + 1e-3);
  CHECK(std::abs(leading.front() - all.front()) <= 1e-8 * std::abs(all.front()));
  // Sandusky, Page & Schmidt, PRB 46, 6161 (1992): 1.02824 (docs/bright-breathers.md)
  CHECK(leading.front().real() == doctest::Approx(1.02824).epsilon(1e-5));
  CHECK(p.krylov.krylov->windowed->sites < 101);  // a window, not the whole ring
  CHECK(distance_to_dense(leading, all) <= 1e-8);
}

TEST_CASE("newton-krylov: dark breathers of a model file as the dense Newton's" * doctest::test_suite("fast")) {
  using namespace jobs::dark;
  struct Case {
    const char* model;
    std::vector<std::pair<std::string, double>> values;
    const char* branch;
    double omega_b;
    Index sites;
  };
  // docs/dark-models.md's klein_gordon (b = -1/2, on-site) and resonant_chain (optical, strain form) breathers.
  for (const Case& k : {Case{"klein_gordon", {{"b", -0.5}}, "", 1.17, 101}, Case{"resonant_chain", {}, "optical", 2.42, 101}}) {
    CAPTURE(k.model);
    const Model model = shipped_model(k.model, k.values);
    DarkConfig c;
    c.step = DarkStep::floquet;
    c.model = &model;
    c.kernels = sim::shipped_lattice_kernels(k.model);
    c.branch = k.branch;
    c.omega_b = k.omega_b;
    c.sites = k.sites;
    c.center = "site";
    c.krylov.floquet_count = 12;
    c.tolerance = 1e-12;  // both Newtons to max|F| <= 1e-12 (they stop at ~1e-14)
    c.krylov.solver = "dense";
    validate(c);
    const DarkResult dense = run(c);
    c.krylov.solver = "krylov";
    validate(c);
    const DarkResult krylov = run(c);
    REQUIRE(!failure(dense));
    REQUIRE(!failure(krylov));
    REQUIRE(krylov.krylov);
    // Measured 2.4e-10 and 2.1e-10: two zeros with max|F| ~ 1e-14 differ by that floor times the
    // shooting Jacobian's condition (~1e4 for these dark breathers on their background), not less.
    CHECK(relative_difference(dense.z0, krylov.z0) <= 5e-10);
    REQUIRE(krylov.krylov->floquet);
    REQUIRE(dense.floquet);
    CHECK(!krylov.krylov->floquet->multipliers.empty());
    CHECK(distance_to_dense(krylov.krylov->floquet->multipliers, dense.floquet->multipliers) <= 1e-8);
  }
}

TEST_CASE("newton-krylov: the solver options refused by their keys" * doctest::test_suite("fast")) {
  jobs::BreatherSolverOptions o;
  auto key = [&] {
    try {
      jobs::validate(o);
    } catch (const InvalidParameter& e) {
      return e.parameter();
    }
    return std::string();
  };
  CHECK(key() == "");
  o.solver = "sparse";
  CHECK(key() == "solver");
  o.solver = "auto";
  o.krylov_band = 0;
  CHECK(key() == "krylov_band");
  o.krylov_band = 12;
  o.floquet_count = 0;
  CHECK(key() == "floquet_count");
  o.floquet_count = 20;
  // auto: the matrix-free path only above krylov_sites.
  CHECK(!jobs::use_krylov(o, 101));
  CHECK(jobs::use_krylov(o, 401));
  o.solver = "krylov";
  CHECK(jobs::use_krylov(o, 41));
}
