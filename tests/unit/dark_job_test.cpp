// The dark-breather job through the library (lrchain/jobs/dark_job.hpp): validate names the DarkConfig
// key of a refused option; a resonant-chain and a klein_gordon breather converge on their band edges;
// a Newton that fails is reported in the result; write() lists an earlier run's files it did not
// rewrite as stale_files. The `lrchain dark` argv mapping is tested in dark_model_cli_test.cpp.
#include <doctest/doctest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <string>
#include <unistd.h>

#include "lrchain/dispersion.hpp"
#include "lrchain/errors.hpp"
#include "lrchain/jobs/dark_job.hpp"
#include "lrchain/model.hpp"
#include "lrchain/sim/model_lattice.hpp"

namespace fs = std::filesystem;
using namespace lrchain;
using namespace lrchain::jobs::dark;

namespace {

// The key validate(c) refuses, or "" when it accepts c.
std::string refused_key(const DarkConfig& c) {
  try {
    validate(c);
  } catch (const InvalidParameter& e) {
    return e.parameter();
  }
  return "";
}

DarkConfig chain(DarkStep step, double omega_b) {
  DarkConfig c;
  c.step = step;
  c.omega_b = omega_b;
  c.sites = 41;
  return c;
}

// klein_gordon with b = -1/2 (defocusing at theta = pi, docs/dark-models.md) on its compiled-in kernels.
struct KleinGordon {
  Model model = shipped_model("klein_gordon", {{"b", -0.5}});
  DarkConfig config(DarkStep step, double omega_b) const {
    DarkConfig c;
    c.step = step;
    c.model = &model;
    c.kernels = sim::shipped_lattice_kernels("klein_gordon");
    c.omega_b = omega_b;
    c.sites = 31;
    return c;
  }
};

}  // namespace

TEST_CASE("dark job: validate refuses by the DarkConfig key, in snake_case" * doctest::test_suite("fast")) {
  // The optical edge at the default Params is omega(pi) = sqrt(6) = 2.449 (test_dark.py).
  CHECK(refused_key(chain(DarkStep::solve, 2.42)) == "");
  CHECK(refused_key(chain(DarkStep::solve, 2.5)) == "omega_b");  // above the edge: lib says "omega-b"
  DarkConfig even = chain(DarkStep::solve, 2.42);
  even.sites = 40;
  CHECK(refused_key(even) == "sites");
  DarkConfig window = chain(DarkStep::branch, 2.42);
  window.omega_min = 2.43;  // sim's validate_continuation_window says "omega-min"
  CHECK(refused_key(window) == "omega_min");
  window.omega_min = 0;
  window.omega_max = -1;
  CHECK(refused_key(window) == "omega_max");
  DarkConfig short_run = chain(DarkStep::evolve, 2.42);
  short_run.t_end = 1;  // T_b = 2 pi / 2.42 = 2.6
  CHECK(refused_key(short_run) == "t_end");
  short_run.t_end = 30;
  short_run.samples = 3;
  CHECK(refused_key(short_run) == "samples");
  const KleinGordon kg;
  CHECK(refused_key(kg.config(DarkStep::solve, 1.17)) == "");
  CHECK(refused_key(kg.config(DarkStep::solve, 1.19)) == "omega_b");  // above the edge sqrt(1.4) = 1.183
  DarkConfig step = kg.config(DarkStep::branch, 1.17);
  step.ds = 2;
  CHECK(refused_key(step) == "ds");
}

TEST_CASE("dark job: the resonant chain's breather at omega_b = 2.42 below the optical edge" * doctest::test_suite("fast")) {
  DarkConfig c = chain(DarkStep::floquet, 2.42);
  validate(c);
  const DarkResult r = run(c);
  REQUIRE(r.newton.converged);
  // The edge is the optical omega(pi) of eq. (9) at the default parameters.
  CHECK(r.edge.omega == doctest::Approx(dispersion_omega(Params{}, Branch::optical, std::numbers::pi)).epsilon(1e-15));
  CHECK(r.measures.E_b <= 1e-10);  // exact to 1e-10 (dark_breather_test.cpp reaches it at 2.42)
  REQUIRE(r.floquet.has_value());
  CHECK(r.monodromy == "reversible reduction");
  CHECK(!failure(r).has_value());
  const nlohmann::json j = to_json(r);
  CHECK(j["failure"].is_null());
  CHECK(j["branch"] == "optical");
  CHECK(j["measures"]["E_b"].get<double>() == r.measures.E_b);
  CHECK(j["floquet"]["multipliers"].size() == r.floquet->multipliers.size());
}

TEST_CASE("dark job: a klein_gordon breather on the model's lattice kernels" * doctest::test_suite("fast")) {
  const KleinGordon kg;
  const DarkConfig c = kg.config(DarkStep::solve, 1.17);
  validate(c);
  const DarkResult r = run(c);
  REQUIRE(r.newton.converged);
  // omega(pi) = sqrt(w0^2 + 4 C) = sqrt(1.4) for the defaults w0 = 1, C = 1/10.
  CHECK(r.edge.omega == doctest::Approx(std::sqrt(1.4)).epsilon(1e-12));
  CHECK(r.edge.branch == "branch0");
  CHECK(!r.edge.mean_flow);  // on-site: displacements u0
  CHECK(r.edge.variables == std::vector<std::string>{"u0"});
  CHECK(r.edge.one_sided_contacts.empty());
  CHECK(!r.contact_changes_per_period.has_value());
  CHECK(r.measures.E_b < 1e-10);
  const nlohmann::json j = to_json(r);
  CHECK(j["model"]["name"] == "klein_gordon");
  CHECK(j["lambda"].is_null());
  CHECK(j["lattice_form"] == "displacement");
  CHECK(j["measures"]["K_y"].is_null());
}

TEST_CASE("dark job: a Newton that does not converge is reported, not thrown" * doctest::test_suite("fast")) {
  DarkConfig c = chain(DarkStep::solve, 2.42);
  c.max_iterations = 1;  // from the seed Newton needs 4 steps at 2.42 (test_dark.py)
  const DarkResult r = run(c);
  CHECK(!r.newton.converged);
  REQUIRE(failure(r).has_value());
  CHECK(failure(r)->find("Newton found no breather at omega_b = 2.42") != std::string::npos);
  CHECK(to_json(r)["failure"]["kind"] == "newton");
}

TEST_CASE("dark job: write lists the files of an earlier run it did not rewrite as stale_files" * doctest::test_suite("fast")) {
  const fs::path out = fs::temp_directory_path() / ("lrchain-dark-job-stale-" + std::to_string(::getpid()));
  fs::remove_all(out);
  fs::create_directories(out);
  std::ofstream(out / "branch.csv") << "from an earlier dark continue\n";
  std::ofstream(out / "profile.csv") << "rewritten by this run\n";
  DarkConfig c = chain(DarkStep::solve, 2.42);
  c.out = out.string();
  validate(c);
  const nlohmann::json j = write(run(c), out);
  CHECK(j["stale_files"] == nlohmann::json::array({"branch.csv"}));
  std::ifstream profile(out / "profile.csv");
  std::string header;
  std::getline(profile, header);
  CHECK(header == "n,x0,y0,x_seed,y_seed,x_T,y_T");
  fs::remove_all(out);
}

TEST_CASE("dark job: without sites, 101 at a theta = pi edge and 100 at a theta = 0 edge" * doctest::test_suite("fast")) {
  DarkConfig chain_default;
  chain_default.omega_b = 2.42;
  CHECK(dark_sites(chain_default) == 101);  // the resonant chain's optical edge is at theta = pi
  // klein_gordon at its defaults: its first defocusing edge is at theta = 0 (`dark solve --model
  // klein_gordon --omega-b 1.1` reports theta 0), so the pair of breathers needs an even ring; with
  // b = -1/2 it is the theta = pi edge (docs/dark-models.md), an odd one.
  const Model defaults = shipped_model("klein_gordon");
  DarkConfig at_zero;
  at_zero.model = &defaults;
  at_zero.kernels = sim::shipped_lattice_kernels("klein_gordon");
  at_zero.omega_b = 1.1;
  CHECK(dark_sites(at_zero) == 100);
  CHECK(refused_key(at_zero) == "");
  at_zero.sites = 101;
  CHECK(refused_key(at_zero) == "sites");
  KleinGordon pi_edge;
  DarkConfig at_pi = pi_edge.config(DarkStep::solve, 1.17);
  at_pi.sites.reset();
  CHECK(dark_sites(at_pi) == 101);
}
