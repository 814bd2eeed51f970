// Provenance (lrchain/provenance.hpp): what every JSON summary and the report say about the
// lrchain that produced them, and `lrchain --version`.
#include <doctest/doctest.h>

#include <filesystem>
#include <fstream>
#include <unistd.h>
#include <nlohmann/json.hpp>
#include <regex>

#include "../support/run_lrchain.hpp"
#include "lrchain/provenance_json.hpp"

using namespace lrchain;
using namespace lrchain::test;

namespace {

// The commit of the source tree when it is a git checkout: 12 hex digits, "-dirty" if modified.
bool is_commit(const std::string& s) { return std::regex_match(s, std::regex("[0-9a-f]{12}(-dirty)?")); }

bool source_is_checkout() { return std::filesystem::exists(std::filesystem::path(LRCHAIN_SOURCE_DIR) / ".git"); }

}  // namespace

TEST_CASE("provenance: build facts, machine, date and this process's command line") {
  const BuildInfo b = build_info();
  CHECK(b.version == LRCHAIN_VERSION_STRING);
  CHECK(std::regex_match(b.version, std::regex(R"(\d+\.\d+\.\d+)")));
  if (source_is_checkout()) CHECK(is_commit(b.commit));
  else CHECK(b.commit.empty());
  CHECK_FALSE(b.compiler.empty());
  const Provenance p = current_provenance();
  CHECK(p.cores >= 1);
  CHECK(std::regex_match(p.date, std::regex(R"(20\d\d-\d\d-\d\dT\d\d:\d\d:\d\dZ)")));
  REQUIRE_FALSE(p.command_line.empty());
  CHECK(std::filesystem::path(p.command_line.front()).filename() == "lrchain-unit-tests");
  const nlohmann::json j = provenance_json(p);
  CHECK(j["lrchain_version"] == b.version);
  CHECK(j["cores"].get<int>() == p.cores);
  CHECK(j["command_line"].size() == p.command_line.size());
}

TEST_CASE("provenance: unknown values are null in JSON, never a sentinel") {
  Provenance p;
  p.build.version = "1.2.3";
  p.date = "2026-01-01T00:00:00Z";
  const nlohmann::json j = provenance_json(p);
  CHECK(j["git_commit"].is_null());
  CHECK(j["compiler"].is_null());
  CHECK(j["build_type"].is_null());
  CHECK(j["cores"].is_null());
  CHECK(j["command_line"].is_null());
}

TEST_CASE("provenance: `lrchain --version` prints the version and commit — summaries carry provenance") {
  const auto v = run_lrchain({"--version"});
  CHECK(v.exit_code == 0);
  CHECK(v.out == version_line() + "\n");
  CHECK(v.out.find(LRCHAIN_VERSION_STRING) != std::string::npos);
  CHECK(v.out.find(source_is_checkout() ? "(commit " + build_info().commit + ")" : "(commit unknown)") !=
        std::string::npos);

  const auto c = run_lrchain({"coeffs", "--theta", "1.2", "--branch", "optical", "--json"});
  REQUIRE(c.exit_code == 0);
  const auto j = nlohmann::json::parse(c.out);
  REQUIRE(j.contains("provenance"));
  const auto& p = j["provenance"];
  CHECK(p["lrchain_version"] == LRCHAIN_VERSION_STRING);
  CHECK(p["command_line"].size() == 7);
  CHECK(p["command_line"][1] == "coeffs");
  CHECK(p["command_line"][6] == "--json");
  CHECK(p["cores"].get<int>() >= 1);

  const auto r = run_lrchain({"regime", "intervals", "--rho", "1/3", "--branch", "acoustic"});
  REQUIRE(r.exit_code == 0);
  CHECK(nlohmann::json::parse(r.out)["provenance"]["command_line"][2] == "intervals");
}

TEST_CASE("provenance: `lrchain sweep --json` carries it next to its own keys") {
  namespace fs = std::filesystem;
  const fs::path dir = fs::temp_directory_path() / ("lrchain-sweep-provenance-" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  fs::copy_file(fs::path(LRCHAIN_SOURCE_DIR) / "examples" / "sweeps" / "base" / "regime_intervals.toml",
                dir / "base.toml");
  // Two points of the shipped regime-intervals sweep (a fraction of a second each).
  std::ofstream(dir / "sweep.toml") << "job = \"regime intervals\"\nbase = \"base.toml\"\noutput = \"out.h5\"\n"
                                       "[[axis]]\nparameter = \"model.rho\"\nfrom = 0.2\nto = 2\ncount = 2\n";
  const auto r = run_lrchain({"sweep", "--config", (dir / "sweep.toml").string(), "--threads", "1", "--quiet", "--json"}, dir);
  REQUIRE(r.exit_code == 0);
  const auto j = nlohmann::json::parse(r.out);
  CHECK(j["points"] == 2);
  CHECK(j["finished"] == 2);
  CHECK(j["job"] == "regime intervals");
  REQUIRE(j.contains("provenance"));
  CHECK(j["provenance"]["lrchain_version"] == LRCHAIN_VERSION_STRING);
  REQUIRE(j["provenance"]["command_line"].size() == 8);
  CHECK(j["provenance"]["command_line"][1] == "sweep");
  CHECK(j["provenance"]["command_line"][7] == "--json");
  fs::remove_all(dir);
}
