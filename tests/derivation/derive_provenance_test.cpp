// `lrchain derive --json` carries the "provenance" object every JSON summary has
// (lrchain/provenance_json.hpp: version, commit, compiler, build type, cores, date, command line),
// next to its own keys.
#include <doctest/doctest.h>

#include <filesystem>
#include <nlohmann/json.hpp>

#include "../support/run_lrchain.hpp"
#include "lrchain/version.hpp"

TEST_CASE("lrchain derive --json: the summary has provenance and keeps its keys") {
  const std::string model = (std::filesystem::path(LRCHAIN_SOURCE_DIR) / "models" / "klein_gordon.toml").string();
  const auto r = lrchain::test::run_lrchain({"derive", "--model", model, "--json"});
  REQUIRE(r.exit_code == 0);
  const auto j = nlohmann::json::parse(r.out);
  for (const char* key : {"model", "parameters", "case", "branches", "coefficients", "checks", "passed"})
    CHECK(j.contains(key));
  REQUIRE(j.contains("provenance"));
  const auto& p = j["provenance"];
  CHECK(p["lrchain_version"] == LRCHAIN_VERSION_STRING);
  CHECK(p["cores"].get<int>() >= 1);
  REQUIRE(p["command_line"].size() == 5);  // lrchain derive --model FILE --json
  CHECK(p["command_line"][1] == "derive");
  CHECK(p["command_line"][3] == model);
  for (const char* key : {"git_commit", "compiler", "build_type", "date"}) CHECK(p.contains(key));
}
