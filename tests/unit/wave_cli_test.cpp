// `lrchain wave solve|continue|stability|standing`: the argv mapping and exit codes (the numbers are the job's,
// wave_job_test.cpp and wave_nls_test.cpp): bad input exits 2 with one line naming the option and writes
// nothing; a solve exits 0 with its JSON; no wave exits 3 with the reason.
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

TEST_CASE("wave cli: bad input exits 2 with one line, nothing written" * doctest::test_suite("fast")) {
  using lrchain::test::check_refused_run;
  const std::vector<std::string> base{"wave", "solve", "--model", "fput", "--branch", "acoustic", "--theta", "2.5"};
  auto with = [&](std::vector<std::string> extra) {
    std::vector<std::string> a = base;
    a.insert(a.end(), extra.begin(), extra.end());
    return a;
  };
  check_refused_run(with({"--amplitude", "-1"}), "invalid amplitude", source_dir);
  check_refused_run(with({"--amplitude", "0.1", "--harmonics", "1"}), "invalid harmonics", source_dir);
  check_refused_run(with({"--amplitude", "0.1", "--tail-tolerance", "2"}), "invalid tail-tolerance", source_dir);
  check_refused_run({"wave", "continue", "--model", "fput", "--branch", "acoustic", "--theta", "2.5", "--amplitudes", "0.2",
                     "0.1"}, "invalid amplitudes", source_dir);
  check_refused_run({"wave", "solve", "--model", "fput", "--branch", "optical", "--theta", "2.5", "--amplitude", "0.1"},
                    "branch", source_dir);
  // The resonant chain has two branches: --branch may not be left out, and the refusal names both.
  check_refused_run({"wave", "solve", "--theta", "2.5", "--amplitude", "0.1"}, "'acoustic', 'optical'", source_dir);
}

TEST_CASE("wave cli: solve exits 0 with its JSON, no wave exits 3" * doctest::test_suite("fast")) {
  // Klein-Gordon has one branch: --branch may be left out (Model::branch_or_only).
  const auto r = run_lrchain({"wave", "solve", "--model", "klein_gordon", "--theta", "3*pi/4",
                              "--amplitude", "0.1", "--json"}, source_dir);
  INFO(r.err);
  REQUIRE(r.exit_code == 0);
  const auto j = nlohmann::json::parse(r.out);
  CHECK(j["model"]["name"] == "klein_gordon");
  CHECK(j["step"] == "solve");
  CHECK(j["branch"] == "branch0");
  CHECK(j["waves"].back()["amplitude"] == doctest::Approx(0.1));
  CHECK(j["profile"]["fields"]["u0"].size() == j["profile"]["xi"].size());
  CHECK(j["failure"].is_null());
  const auto lost = run_lrchain({"wave", "continue", "--branch", "optical", "--theta", "pi/2", "--amplitudes", "0.2", "0.4",
                                 "--json"}, source_dir);
  CHECK(lost.exit_code == 3);
  CHECK(lost.err.find("contact") != std::string::npos);
  CHECK(nlohmann::json::parse(lost.out)["failed_at"] == doctest::Approx(0.4));
}

TEST_CASE("wave cli: standing maps its options, writes its files, refuses theta at pi" * doctest::test_suite("fast")) {
  using lrchain::test::check_refused_run;
  check_refused_run({"wave", "standing", "--model", "fput", "--theta", "3.1", "--amplitude", "0.02", "--ring-sites", "20"},
                    "invalid theta", source_dir);
  check_refused_run({"wave", "standing", "--model", "fput", "--theta", "1", "--amplitude", "0.02", "--ring-sites", "4"},
                    "invalid ring-sites", source_dir);
  check_refused_run({"wave", "standing", "--model", "fput", "--theta", "1", "--amplitude", "0.02", "--ring-sites", "20",
                     "--format", "netcdf"},
                    "--format", source_dir);
  const fs::path out = fs::temp_directory_path() / ("lrchain-wave-standing-cli-" + std::to_string(::getpid()));
  const auto r = run_lrchain({"wave", "standing", "--model", "fput", "--theta", "2*pi/5", "--amplitude", "0.02",
                              "--ring-sites", "20", "--ramp", "2", "--json", "--out", out.string(), "--format", "hdf5"},
                             source_dir);
  INFO(r.err);
  REQUIRE(r.exit_code == 0);
  const auto j = nlohmann::json::parse(r.out);
  CHECK(j["step"] == "standing");
  CHECK(j["options"]["ring_sites"] == 20);
  CHECK(j["standing"]["waves"].size() == 2);
  CHECK(j["standing"]["period_sites"] == 5);
  for (const char* file : {"standing.csv", "standing_profile.csv", "floquet.csv", "floquet.gp", "summary.json", "result.h5"})
    CHECK_MESSAGE(fs::exists(out / file), file);
  fs::remove_all(out);
}
