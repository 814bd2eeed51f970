// `lrchain simulate ring|bright --model` and model-file bright configs: bad input exits 2 with one
// line naming the option and writes nothing; the shipped model configs load to their values; a
// short ring run prints its JSON (the numerical checks are validation tests).
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <string>
#include <unistd.h>

#include <nlohmann/json.hpp>

#include "lrchain/jobs/model_experiment_config.hpp"
#include "../support/refusal_checks.hpp"
#include "../support/run_lrchain.hpp"

namespace fs = std::filesystem;
using lrchain::test::run_lrchain;

namespace {

const fs::path source_dir = LRCHAIN_SOURCE_DIR;

void check_refused(const std::vector<std::string>& args, const std::string& needle) {
  lrchain::test::check_refused_run(args, needle, source_dir);
}

}  // namespace

TEST_CASE("model simulate: bad options exit 2 naming the option, before anything is written" * doctest::test_suite("fast")) {
  check_refused({"simulate", "ring", "--model", "models/fput.toml", "--branch", "acoustic", "--theta", "1"}, "theta");
  check_refused({"simulate", "ring", "--model", "models/fput.toml", "--branch", "optical", "--theta", "pi/2"}, "branch");
  check_refused({"simulate", "ring", "--model", "models/fput.toml", "--branch", "acoustic", "--theta", "pi/2",
                 "--amplitudes", "0.02", "-1"}, "amplitudes");
  check_refused({"simulate", "ring", "--model", "models/fput.toml", "--branch", "acoustic", "--theta", "pi/2",
                 "--set", "c=1"}, "c");
  check_refused({"simulate", "bright", "--model", "models/homogeneous_chain.toml", "--branch", "acoustic", "--theta",
                 "pi/2"}, "not focusing");
  check_refused({"simulate", "bright", "--model", "models/klein_gordon.toml", "--branch", "branch0", "--theta",
                 "3*pi/4", "--detuning", "-1e-4"}, "detuning");
  check_refused({"simulate", "bright", "--model", "models/fput.toml", "--branch", "acoustic", "--theta", "pi/2",
                 "--rho", "1"}, "--rho");
  // --format takes csv or hdf5 (check_refused_run adds --out; without it cli_usage_test's refusal applies).
  check_refused({"simulate", "ring", "--model", "models/fput.toml", "--branch", "acoustic", "--theta", "pi/2",
                 "--format", "h5"}, "--format");
  check_refused({"simulate", "bright", "--model", "models/fput.toml", "--branch", "acoustic", "--theta", "pi/2",
                 "--format", "h5"}, "--format");
}

TEST_CASE("model simulate: --format hdf5 writes result.h5 and summary.json, no CSV and no figures" *
          doctest::test_suite("fast")) {
  const fs::path out = fs::temp_directory_path() / ("lrchain-model-hdf5-" + std::to_string(::getpid()));
  fs::remove_all(out);
  for (const std::vector<std::string>& run :
       {std::vector<std::string>{"simulate", "ring", "--model", "models/fput.toml", "--branch", "acoustic", "--theta",
                                 "pi/2", "--periods", "20", "--packet-width", "8"},
        std::vector<std::string>{"simulate", "bright", "--model", "models/fput.toml", "--branch", "acoustic",
                                 "--theta", "pi/2", "--sites", "41", "--periods", "1"}}) {
    std::vector<std::string> args = run;
    args.insert(args.end(), {"--out", out.string(), "--format", "hdf5", "--json"});
    const auto r = run_lrchain(args, source_dir);
    INFO(r.err);
    REQUIRE(r.exit_code == 0);
    std::vector<std::string> written;
    for (const auto& e : fs::directory_iterator(out)) written.push_back(e.path().filename().string());
    std::sort(written.begin(), written.end());
    CHECK(written == std::vector<std::string>{"result.h5", "summary.json"});
    CHECK(fs::file_size(out / "result.h5") > 1000);
    fs::remove_all(out);
  }
}

TEST_CASE("model simulate: a short ring run reports omega, h and both amplitudes" * doctest::test_suite("fast")) {
  const auto r = run_lrchain({"simulate", "ring", "--model", "models/klein_gordon.toml", "--branch", "branch0",
                              "--theta", "pi/2", "--periods", "50", "--json"},
                             source_dir);
  INFO(r.err);
  REQUIRE(r.exit_code == 0);
  const auto j = nlohmann::json::parse(r.out);
  CHECK(j["model"]["name"] == "klein_gordon");
  CHECK(j["sites"] == 8);
  // omega^2 = w0^2 + 4 C sin^2(theta/2) = 1 + 0.2 at the defaults (C = 1/10, w0 = 1).
  CHECK(j["prediction"]["omega"].get<double>() == doctest::Approx(std::sqrt(1.2)).epsilon(1e-12));
  REQUIRE(j["amplitudes"].size() == 2);
  CHECK(j["amplitudes"][0]["relative_disagreement"].get<double>() < 0.01);
}

TEST_CASE("model simulate: the shipped model configs pass their schema — unknown keys are errors" * doctest::test_suite("fast")) {
  int loaded = 0;
  for (const auto& entry : fs::directory_iterator(source_dir / "examples" / "models")) {
    if (entry.path().extension() != ".toml") continue;
    INFO(entry.path().string());
    const auto doc = lrchain::config::Document::from_file(entry.path());
    REQUIRE(lrchain::jobs::is_model_experiment(doc));
    const auto c = lrchain::jobs::load_model_experiment_config(doc);
    CHECK(fs::exists(source_dir / c.model_file));
    if (c.experiment == "bright") CHECK(c.bright.periods == 200);
    if (c.experiment == "ring") CHECK(c.ring.amplitudes == std::vector<double>{0.02, 0.01});
    ++loaded;
  }
  CHECK(loaded == 7);
  const auto fput = lrchain::jobs::load_model_experiment_config(
      lrchain::config::Document::from_file(source_dir / "examples" / "models" / "fput_bright.toml"));
  CHECK(fput.parameters.size() == 2);
  CHECK(fput.parameters[0].first == "a");
  CHECK(fput.parameters[0].second == 0.25);
  CHECK(fput.bright.N == 2000);
  const std::string bad = "experiment = \"bright\"\nmodel = \"models/fput.toml\"\n[bright]\nbranch = \"acoustic\"\n"
                          "theta = \"pi/2\"\nstepper = \"rkf78\"\n";
  const auto doc = lrchain::config::Document::from_text(bad, "bad.toml");
  CHECK_THROWS_WITH_AS(lrchain::jobs::load_model_experiment_config(doc), doctest::Contains("stepper"),
                       lrchain::config::ConfigError);
}

TEST_CASE("model simulate: a model config's [bright] sites is the odd count 2N + 1 — the old key N is refused" *
          doctest::test_suite("fast")) {
  const std::string head = "experiment = \"bright\"\nmodel = \"models/fput.toml\"\n[bright]\nbranch = \"acoustic\"\n"
                           "theta = \"pi/2\"\n";  // lines 1-5
  const auto load = [&](const std::string& line) {
    return lrchain::jobs::load_model_experiment_config(lrchain::config::Document::from_text(head + line, "m.toml"));
  };
  const auto error = [&](const std::string& line) {
    try {
      load(line);
    } catch (const lrchain::config::ConfigError& e) {
      return std::string(e.what());
    }
    return std::string("loaded");
  };
  CHECK(load("sites = 21\n").bright.N == 10);  // n = -10..10
  CHECK(load("").bright.N == lrchain::sim::ModelBrightConfig{}.N);
  CHECK(error("sites = 100\n") ==
        "invalid value for 'sites' in [bright] at m.toml:6: must be an odd integer in [21, 100000001]: the "
        "sites are n = -N..N, 2N + 1 of them (got 100)");
  CHECK(error("sites = 19\n") == "invalid value for 'sites' in [bright] at m.toml:6: expected an integer in [21, "
                                  "100000001]; got 19");
  CHECK(error("N = 500\n") == "key 'N' in [bright] at m.toml:6 was renamed: use 'sites', the number of strain sites "
                              "2N + 1 (the old N was the half-width)");
  // The run's own checks are located too: n0 = 11 lies outside n = -10..10 of 21 sites.
  CHECK(error("sites = 21\nn0 = 11\n") == "invalid value for 'n0' in [bright] at m.toml:7: the initial centre must be "
                                           "in [-N, N] = [-10, 10] (sites = 2N + 1 = 21)");
}

TEST_CASE("model simulate: a ring config gives the numbers of the same ring run from options" * doctest::test_suite("fast")) {
  // Two routes to one run: examples/models/homogeneous_chain_ring.toml and the same values as
  // options. The shift's disagreement with h U^2/4 is O(U^2): about 4x smaller at U/2.
  const auto config = run_lrchain({"simulate", "--config", "examples/models/homogeneous_chain_ring.toml", "--json"}, source_dir);
  const auto options = run_lrchain({"simulate", "ring", "--model", "models/homogeneous_chain.toml", "--set", "alpha=1.5",
                                    "--set", "delta0=4/9", "--branch", "acoustic", "--theta", "pi/4", "--amplitudes",
                                    "0.02", "0.01", "--json"},
                                   source_dir);
  INFO(config.err, options.err);
  REQUIRE(config.exit_code == 0);
  REQUIRE(options.exit_code == 0);
  const auto a = nlohmann::json::parse(config.out), b = nlohmann::json::parse(options.out);
  CHECK(a["name"] == "homogeneous-chain-ring-pi-4");
  CHECK(a["amplitudes"] == b["amplitudes"]);
  CHECK(a["packet"] == b["packet"]);
  const double e0 = a["amplitudes"][0]["relative_disagreement"], e1 = a["amplitudes"][1]["relative_disagreement"];
  CHECK(e0 < 0.01);
  CHECK(e1 < e0 / 3);
  // A [bright] table in a ring config is another experiment's table: refused, naming it.
  const std::string bad = "experiment = \"ring\"\nmodel = \"models/fput.toml\"\n[bright]\nbranch = \"acoustic\"\n"
                          "theta = \"pi/2\"\n";
  CHECK_THROWS_WITH_AS(lrchain::jobs::load_model_experiment_config(lrchain::config::Document::from_text(bad, "bad.toml")),
                       doctest::Contains("[bright]"), lrchain::config::ConfigError);
}
