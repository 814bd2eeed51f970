// `lrchain dark ... --model`: bad input exits 2 with one line naming the option (or the edges
// checked) and writes nothing; a small klein_gordon solve prints the model's provenance and
// writes its profile. The numerical checks are validation tests (dark_model_test.cpp).
#include <doctest/doctest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <string>
#include <unistd.h>

#include <nlohmann/json.hpp>

#include "../support/refusal_checks.hpp"
#include "../support/renamed_model.hpp"
#include "../support/run_lrchain.hpp"

namespace fs = std::filesystem;
using lrchain::test::run_lrchain;

namespace {

const fs::path source_dir = LRCHAIN_SOURCE_DIR;

// A dark job given --quiet (no Newton progress on stderr), refused.
void check_refused(std::vector<std::string> args, const std::string& needle) {
  args.push_back("--quiet");
  lrchain::test::check_refused_run(args, needle, source_dir);
}

}  // namespace

TEST_CASE("dark --model: bad input exits 2 with one line, nothing written" * doctest::test_suite("fast")) {
  // fput: focusing at theta = pi (omega'' h < 0), no real frequency at theta = 0 on its acoustic branch.
  check_refused({"dark", "solve", "--model", "models/fput.toml", "--omega-b", "1.9"},
                "fput has no defocusing band edge for dark breathers (edges checked: acoustic at theta = pi: focusing");
  // klein_gordon's defaults: the theta = 0 edge, an odd ring given by hand is refused (the default is 100).
  check_refused({"dark", "solve", "--model", "models/klein_gordon.toml", "--omega-b", "1.1", "--sites", "101"},
                "theta = 0");
  check_refused({"dark", "solve", "--model", "models/klein_gordon.toml", "--set", "b=-1/2", "--omega-b", "1.19"},
                "omega-b");
  check_refused({"dark", "solve", "--model", "models/klein_gordon.toml", "--set", "b=-1/2", "--omega-b", "1.17",
                 "--sites", "60"}, "sites");
  check_refused({"dark", "floquet", "--model", "models/diatomic_chain.toml", "--omega-b", "1.72", "--sites", "41"},
                "even");
  check_refused({"dark", "solve", "--model", "models/klein_gordon.toml", "--set", "b=-1/2", "--omega-b", "1.17",
                 "--branch", "optical"}, "branch");
  check_refused({"dark", "solve", "--model", "models/klein_gordon.toml", "--set", "bb=1", "--omega-b", "1.17"}, "bb");
  check_refused({"dark", "solve", "--model", "models/klein_gordon.toml", "--set", "b=-1/2", "--omega-b", "1.17",
                 "--rho", "1"}, "--rho");
  check_refused({"dark", "floquet", "--model", "models/klein_gordon.toml", "--set", "b=-1/2", "--omega-b", "1.17",
                 "--full-monodromy"}, "--full-monodromy");
  check_refused({"dark", "evolve", "--model", "models/klein_gordon.toml", "--set", "b=-1/2", "--omega-b", "1.17",
                 "--t-end", "1"}, "t-end");
  check_refused({"dark", "continue", "--model", "models/klein_gordon.toml", "--set", "b=-1/2", "--omega-b", "1.17",
                 "--omega-min", "1.2"}, "omega-min");
  // A stable breather (docs/dark-models.md: Floquet stable at omega_b = 1.17) has no unstable direction.
  check_refused({"dark", "evolve", "--model", "models/klein_gordon.toml", "--set", "b=-1/2", "--omega-b", "1.17",
                 "--sites", "31", "--t-end", "10", "--perturb", "unstable"}, "perturb: unstable needs an unstable breather");
  check_refused({"dark", "solve", "--set", "rho=1", "--omega-b", "2.44"}, "--model");
  check_refused({"dark", "solve", "--omega-b", "2.44", "--branch", "middle"}, "branch");
}

TEST_CASE("dark --model: exit 0, the model's JSON, profile.csv and an earlier run's file as stale" * doctest::test_suite("fast")) {
  // The numbers are the job's (dark_job_test.cpp); here the argv mapping, the exit code and the files.
  const fs::path out = fs::temp_directory_path() / ("lrchain-dark-model-solve-" + std::to_string(::getpid()));
  fs::remove_all(out);
  fs::create_directories(out);
  std::ofstream(out / "evolution.csv") << "from an earlier dark evolve\n";
  const auto r = run_lrchain({"dark", "solve", "--model", "models/klein_gordon.toml", "--set", "b=-1/2", "--omega-b",
                              "1.17", "--sites", "31", "--quiet", "--figure-format", "png", "--out", out.string()},
                             source_dir);
  INFO(r.err);
  REQUIRE(r.exit_code == 0);
  const auto j = nlohmann::json::parse(r.out);
  CHECK(j["model"]["name"] == "klein_gordon");
  CHECK(j["model"]["parameters"]["b"] == doctest::Approx(-0.5));
  CHECK(j["sites"] == 31);
  CHECK(j["newton_converged"] == true);
  CHECK(j["stale_files"] == nlohmann::json::array({"evolution.csv"}));
  CHECK(fs::exists(out / "profile.csv"));
  fs::remove_all(out);
}

TEST_CASE("dark --model: the Morse chain of issue 27 is refused below its edge, solved above it" * doctest::test_suite("fast")) {
  // h = 14 > 0, h_tilde = -22 at theta = pi (`lrchain coeffs`): with the far-field mean strain fixed to
  // zero the background's frequency is 2 + h A^2, so no dark breather lies below the edge (main
  // "converged" there to an irregular profile with exit 0) and one lies above it.
  const fs::path dir = fs::temp_directory_path() / ("lrchain-dark-morse-" + std::to_string(::getpid()));
  fs::remove_all(dir);
  const std::vector<std::string> cache{"XDG_CACHE_HOME=" + (dir / "cache").string()};
  const auto below = run_lrchain({"dark", "floquet", "--model", "tests/data/models/morse.toml", "--omega-b", "1.99",
                                  "--sites", "61", "--quiet", "--out", (dir / "out").string()},
                                 source_dir, cache);
  INFO(below.err);
  CHECK(below.exit_code == 2);
  CHECK(below.out.empty());
  CHECK(std::count(below.err.begin(), below.err.end(), '\n') == 1);
  CHECK(below.err.find("invalid omega-b: must lie above omega = 2") != std::string::npos);
  CHECK(below.err.find("h = 14") != std::string::npos);
  CHECK(!fs::exists(dir / "out"));
  const auto above = run_lrchain({"dark", "solve", "--model", "tests/data/models/morse.toml", "--omega-b", "2.002",
                                  "--sites", "61", "--quiet"},
                                 source_dir, cache);
  INFO(above.err);
  CHECK(above.exit_code == 0);
  CHECK(nlohmann::json::parse(above.out)["failure"].is_null());
  fs::remove_all(dir);
}
