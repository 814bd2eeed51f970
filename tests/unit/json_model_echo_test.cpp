// Every JSON output echoes the model in one shape, "model": {"name", "file_hash", "parameters"},
// the object `coeffs --json` prints, and names the lattice size "sites" with the value --sites
// takes: simulate summaries (stdout and summary.json), dark solve|continue|evolve, regime
// intervals|map|thresholds. The old keys ("params", "N", "beads", top-level "rho", ...) are gone.
#include <doctest/doctest.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <unistd.h>
#include <vector>

#include <nlohmann/json.hpp>

#include "lrchain/model.hpp"
#include "../support/run_lrchain.hpp"

namespace fs = std::filesystem;
using lrchain::test::run_lrchain;
using nlohmann::json;

namespace {

const fs::path source_dir = LRCHAIN_SOURCE_DIR;

// A scratch directory for one test case, removed at the end.
struct ScratchDir {
  fs::path path;
  explicit ScratchDir(const std::string& name)
      : path(fs::temp_directory_path() / ("lrchain-json-echo-" + name + "-" + std::to_string(::getpid()))) {
    fs::remove_all(path);
    fs::create_directories(path);
  }
  ~ScratchDir() { fs::remove_all(path); }
};

// `lrchain args...` (exit 0 required) and its JSON on stdout.
json run_json(const std::vector<std::string>& args) {
  const auto r = run_lrchain(args, source_dir);
  INFO(r.err);
  REQUIRE(r.exit_code == 0);
  return json::parse(r.out);
}

json read_json(const fs::path& file) {
  std::ifstream in(file);
  REQUIRE(in);
  return json::parse(in);
}

// The model object of `coeffs --json` for the resonant chain at these --rho/--kappa values: the
// reference shape every other output must equal.
json coeffs_model(const std::string& rho, const std::string& kappa) {
  return run_json({"coeffs", "--theta", "pi/2", "--branch", "optical", "--rho", rho, "--kappa", kappa,
                   "--json"})["model"];
}

// The resonant chain's model object at (rho, kappa) with the default alpha = 3/2 and delta0 = 4/9:
// name, the shipped file's hash, and each parameter within 1e-15 of the value given.
void check_resonant_model(const json& model, double rho, double kappa) {
  REQUIRE(model.is_object());
  CHECK(model.size() == 3);
  CHECK(model["name"] == "resonant_chain");
  CHECK(model["file_hash"] == lrchain::model_hash_text(lrchain::find_shipped_model("resonant_chain")->file_hash));
  const json& p = model["parameters"];
  CHECK(p.size() == 4);
  CHECK(p["rho"].get<double>() == doctest::Approx(rho).epsilon(1e-15));
  CHECK(p["kappa"].get<double>() == doctest::Approx(kappa).epsilon(1e-15));
  CHECK(p["alpha"].get<double>() == doctest::Approx(1.5).epsilon(1e-15));
  CHECK(p["delta0"].get<double>() == doctest::Approx(4.0 / 9).epsilon(1e-15));
}

void check_absent(const json& j, const std::vector<std::string>& keys) {
  for (const auto& key : keys) {
    INFO("key " << key);
    CHECK_FALSE(j.contains(key));
  }
}

const std::vector<std::string> old_parameter_keys = {"params", "parameters", "rho", "kappa", "delta0", "alpha"};

}  // namespace

TEST_CASE("simulate bright: summary echoes the model as coeffs does and its size as --sites") {
  ScratchDir dir("bright");
  const json j = run_json({"simulate", "bright", "--branch", "optical", "--theta", "pi/2", "--rho", "1/2", "--kappa",
                           "2", "--sites", "41", "--periods", "1", "--no-figures", "--out", (dir.path / "run").string(),
                           "--json"});
  check_resonant_model(j["model"], 0.5, 2.0);
  CHECK(j["model"] == coeffs_model("1/2", "2"));
  CHECK(j["sites"] == 41);  // n = -20..20
  check_absent(j, old_parameter_keys);
  check_absent(j, {"N", "half_width"});
  const json file = read_json(dir.path / "run" / "summary.json");
  CHECK(file["model"] == j["model"]);
  CHECK(file["sites"] == 41);
  check_absent(file, {"params", "N"});
}

TEST_CASE("simulate drive and modulated: sites, switch_off_time and modulation_depth as the options name them") {
  const json d = run_json({"simulate", "drive", "--rho", "10", "--sites", "50", "--t-end", "4", "--switch-off-time", "2",
                           "--sample-every", "1", "--spacetime-every", "2", "--front-fit-start", "0",
                           "--front-fit-end", "4", "--json"});
  check_resonant_model(d["model"], 10.0, 1.0);
  CHECK(d["sites"] == 50);
  CHECK(d["drive"]["switch_off_time"].get<double>() == doctest::Approx(2.0).epsilon(1e-15));
  check_absent(d, old_parameter_keys);
  check_absent(d, {"beads"});
  check_absent(d["drive"], {"t_m"});

  const json m = run_json({"simulate", "modulated", "--sites", "21", "--theta-waves", "13", "--modulation-depth",
                           "0.02", "--t-end", "4", "--sample-every", "1", "--speed-fit-start", "0", "--speed-fit-end",
                           "4", "--json"});
  // The modulated run's default parameters: rho = 0.32, delta0 = 0.27 (kappa = 1, alpha = 3/2).
  REQUIRE(m["model"]["name"] == "resonant_chain");
  CHECK(m["model"]["parameters"]["rho"].get<double>() == doctest::Approx(0.32).epsilon(1e-15));
  CHECK(m["model"]["parameters"]["delta0"].get<double>() == doctest::Approx(0.27).epsilon(1e-15));
  CHECK(m["sites"] == 21);
  CHECK(m["initial"]["modulation_depth"].get<double>() == doctest::Approx(0.02).epsilon(1e-15));
  check_absent(m, old_parameter_keys);
  check_absent(m, {"N"});
  check_absent(m["initial"], {"b"});
}

TEST_CASE("simulate bright --model: sites is the --sites value") {
  const json j = run_json({"simulate", "bright", "--model", "models/fput.toml", "--branch", "acoustic", "--theta",
                           "pi/2", "--sites", "41", "--periods", "1", "--json"});
  CHECK(j["model"]["name"] == "fput");
  CHECK(j["model"]["lattice_code"]["compiled_in"] == true);
  CHECK(j["sites"] == 41);
  check_absent(j, {"N", "params"});
}

TEST_CASE("dark solve, continue and evolve echo the model object, not loose parameters") {
  const std::vector<std::string> job = {"--omega-b", "2.42", "--sites", "21", "--rho", "1/3", "--kappa", "1", "--quiet",
                                        "--json"};
  auto with = [&job](std::vector<std::string> command) {
    command.insert(command.end(), job.begin(), job.end());
    return command;
  };
  for (const json& j : {run_json(with({"dark", "solve"})),
                        run_json(with({"dark", "continue", "--points", "2", "--ds", "0.05"})),
                        run_json(with({"dark", "evolve", "--t-end", "6"}))}) {
    check_resonant_model(j["model"], 1.0 / 3, 1.0);
    CHECK(j["model"] == coeffs_model("1/3", "1"));
    CHECK(j["sites"] == 21);
    check_absent(j, old_parameter_keys);
  }
}

TEST_CASE("regime intervals, map and thresholds echo the model object, not params") {
  const json in = run_json({"regime", "intervals", "--rho", "10", "--kappa", "2", "--branch", "optical", "--json"});
  check_resonant_model(in["model"], 10.0, 2.0);
  CHECK(in["model"] == coeffs_model("10", "2"));
  check_absent(in, old_parameter_keys);

  ScratchDir dir("regime");
  for (const char* plane : {"theta-rho", "delta0-omega"}) {
    INFO("plane " << plane);
    const json map = run_json({"regime", "map", "--plane", plane, "--branch", "optical", "--kappa", "2", "--nx", "8",
                               "--ny", "8", "--no-curves", "--no-figures", "--out", (dir.path / plane).string()});
    check_resonant_model(map["model"], 1.0 / 3, 2.0);
    check_absent(map, old_parameter_keys);
    for (const json& m : map.value("maps", json::array())) check_absent(m, old_parameter_keys);
  }

  // The paper's scenarios (Sec. 3.3): each names its own base point, e.g. rho = 3 for the delta0 scans.
  const json th = run_json({"regime", "thresholds", "--scan", "10", "--json"});
  REQUIRE_FALSE(th["scenarios"].empty());
  bool rho3 = false;
  for (const json& s : th["scenarios"]) {
    REQUIRE(s["model"]["name"] == "resonant_chain");
    CHECK(s["model"]["parameters"].size() == 4);
    check_absent(s, {"params"});
    rho3 = rho3 || (s["axis"] == "delta0" && s["model"]["parameters"]["rho"].get<double>() == doctest::Approx(3.0));
  }
  CHECK(rho3);
}
