// `lrchain bright solve|floquet`: bad input exits 2 with one line naming the option and writes
// nothing; a solve exits 0 with its JSON and files; a converged zero that is no localized breather
// exits 3. The numbers are the job's (bright_breather_job_test.cpp); here the argv mapping and exit codes.
#include <doctest/doctest.h>

#include <filesystem>
#include <string>
#include <unistd.h>

#include <nlohmann/json.hpp>

#include "../support/refusal_checks.hpp"
#include "../support/run_lrchain.hpp"

namespace fs = std::filesystem;
using lrchain::test::run_lrchain;

static const fs::path source_dir = LRCHAIN_SOURCE_DIR;

// `lrchain bright ...` refused with one line containing `needle`.
static void check_refused(std::vector<std::string> args, const std::string& needle) {
  args.push_back("--quiet");  // no Newton progress on stderr
  lrchain::test::check_refused_run(args, needle, source_dir);
}

TEST_CASE("bright cli: bad input exits 2 with one line, nothing written" * doctest::test_suite("fast")) {
  check_refused({"bright", "solve", "--model", "klein_gordon", "--omega-b", "1.1"}, "invalid omega-b: omega_b = 1.1 lies inside");
  check_refused({"bright", "solve", "--model", "klein_gordon", "--set", "C=1", "--set", "a=0", "--set", "b=-1/2",
                 "--omega-b", "0.97"}, "harmonic 2 omega_b");
  check_refused({"bright", "solve", "--omega-b", "2.5"}, "resonant_chain has no focusing band edge");
  check_refused({"bright", "solve", "--model", "klein_gordon", "--omega-b", "1.19", "--sites", "60"}, "invalid sites");
  check_refused({"bright", "floquet", "--model", "klein_gordon", "--omega-b", "1.19", "--tail-tolerance", "2"},
                "invalid tail-tolerance");
  check_refused({"bright", "floquet", "--model", "klein_gordon", "--omega-b", "1.19", "--unit-tolerance", "0"},
                "invalid unit-tolerance");
  check_refused({"bright", "solve", "--model", "klein_gordon", "--omega-b", "1.19", "--rho", "1"}, "--rho");
  check_refused({"bright", "solve", "--model", "klein_gordon", "--omega-b", "1.19", "--branch", "optical"}, "branch");
}

TEST_CASE("bright cli: floquet exits 0 with its JSON and files, a wave on the ring exits 3" * doctest::test_suite("fast")) {
  const fs::path out = fs::temp_directory_path() / ("lrchain-bright-cli-" + std::to_string(::getpid()));
  fs::remove_all(out);
  const auto r = run_lrchain({"bright", "floquet", "--model", "fput", "--set", "a=0", "--center", "bond", "--omega-b",
                              "2.2", "--sites", "41", "--quiet", "--out", out.string()}, source_dir);
  INFO(r.err);
  REQUIRE(r.exit_code == 0);
  const auto j = nlohmann::json::parse(r.out);
  CHECK(j["model"]["name"] == "fput");
  CHECK(j["center"] == "bond");
  CHECK(j["sites"] == 41);
  CHECK(j["newton_converged"] == true);
  CHECK(j["floquet"]["stable"] == true);
  CHECK(j["failure"].is_null());
  for (const char* file : {"profile.csv", "multipliers.csv", "summary.json"}) CHECK(fs::exists(out / file));
  fs::remove_all(out);
  const auto wave = run_lrchain({"bright", "solve", "--model", "fput", "--set", "a=0", "--omega-b", "2.05", "--sites",
                                 "41", "--quiet", "--json", "--out", out.string()}, source_dir);
  CHECK(wave.exit_code == 3);
  CHECK(wave.err.find("not localized") != std::string::npos);
  CHECK(nlohmann::json::parse(wave.out)["failure"]["kind"] == "not_a_bright_breather");
  CHECK(!fs::exists(out / "profile.csv"));
  fs::remove_all(out);
}
