// Strict configs (lrchain/config/strict_toml.hpp and the simulate schemas): every problem is one
// located message with the key, line and suggestion; the shipped examples still load to the values
// written in them; the CLI exits 2 and writes nothing; docs/configs.md matches the schema.
#include <doctest/doctest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <sstream>
#include <string>
#include <unistd.h>

#include "lrchain/config/strict_toml.hpp"
#include "lrchain/process.hpp"
#include "lrchain/jobs/experiment_config.hpp"
#include "lrchain/jobs/more_experiment_config.hpp"

namespace fs = std::filesystem;
using lrchain::config::ConfigError;
using lrchain::config::Document;

namespace {

const std::string bright_head =
    "experiment = \"bright\"\n"  // 1
    "name = \"t\"\n"             // 2
    "\n"                         // 3
    "[model]\n"                  // 4
    "rho = \"1/3\"\n";           // 5

const std::string drive_head =
    "experiment = \"drive\"\n"  // 1
    "\n"                        // 2
    "[drive]\n";                // 3

const std::string modulated_head =
    "experiment = \"modulated\"\n"  // 1
    "\n"                            // 2
    "[modulated]\n";                // 3

// Loads `text` as the file `source` with the reader of its kind; returns the ConfigError message
// ("" when it loads).
std::string load_error(const std::string& text, const std::string& source, ConfigError* error = nullptr) {
  try {
    const Document doc = Document::from_text(text, source);
    const std::string kind = lrchain::jobs::experiment_kind(doc);
    if (kind == "drive") lrchain::jobs::load_drive_config(doc);
    else if (kind == "modulated") lrchain::jobs::load_modulated_config(doc);
    else lrchain::jobs::load_experiment_config(doc);
  } catch (const ConfigError& e) {
    if (error) *error = e;
    return e.what();
  }
  return "";
}

std::string slurp(const fs::path& p) {
  std::ifstream in(p);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

fs::path example(const std::string& name) { return fs::path(LRCHAIN_SOURCE_DIR) / "examples" / name; }

}  // namespace

TEST_CASE("config: an unknown key names file, line, table and the closest valid key") {
  ConfigError e("", "", 0, "", "");
  CHECK(load_error(bright_head + "kapa = 5\n[bright]\ntheta = \"pi/2\"\n", "exp1.toml", &e) ==
        "unknown key 'kapa' in [model] at exp1.toml:6; did you mean 'kappa'?");
  CHECK(e.line() == 6);
  CHECK(e.table() == "model");
  CHECK(e.key() == "kapa");
  // steper = "dopri5" is an error, not a silent rkf78.
  CHECK(load_error(bright_head + "[bright]\ntheta = 1\n[integrator]\nsteper = \"dopri5\"\n", "exp1.toml") ==
        "unknown key 'steper' in [integrator] at exp1.toml:9; did you mean 'stepper'?");
  // Top level, and a key nowhere near a valid one: the allowed keys are listed.
  CHECK(load_error("experiment = \"bright\"\nnmae = \"x\"\n[bright]\ntheta = 1\n", "a.toml") ==
        "unknown key 'nmae' in the top-level table at a.toml:2; did you mean 'name'?");
  CHECK(load_error(bright_head + "zzz = 1\n[bright]\ntheta = 1\n", "a.toml") ==
        "unknown key 'zzz' in [model] at a.toml:6; allowed here: 'rho', 'kappa', 'delta0', 'alpha'");
}

TEST_CASE("config: an unknown table, or another experiment's table, is an error") {
  CHECK(load_error("experiment = \"bright\"\n[modle]\nrho = 1\n[bright]\ntheta = 1\n", "a.toml") ==
        "unknown table [modle] at a.toml:2; did you mean [model]?");
  CHECK(load_error("experiment = \"bright\"\n[bright]\ntheta = 1\n[drive]\nsites = 10\n", "a.toml") ==
        "unknown table [drive] at a.toml:4; allowed here: 'experiment', 'name', [model], [bright], [integrator], "
        "[output]");
}

TEST_CASE("config: wrong types name the key, the line and the expected type") {
  CHECK(load_error(bright_head + "[bright]\ntheta = 1\n[integrator]\nstepper = 5\n", "exp1.toml") ==
        "wrong type for 'stepper' in [integrator] at exp1.toml:9: expected one of \"rkf78\", \"dopri5\", "
        "\"symplectic\", \"srkn11b\", \"srkn14a\", \"ss17\"; got the integer 5");
  CHECK(load_error(bright_head + "[bright]\ntheta = 1\nansatz_ends = \"yes\"\n", "exp4c.toml") ==
        "wrong type for 'ansatz_ends' in [bright] at exp4c.toml:8: expected true or false; got the string \"yes\"");
  CHECK(load_error(bright_head + "[bright]\ntheta = true\n", "a.toml") ==
        "wrong type for 'theta' in [bright] at a.toml:7: expected a finite number (a TOML number, or a number "
        "string such as \"1/3\" or \"3*pi/5\"); got the boolean true");
  CHECK(load_error(bright_head + "[bright]\ntheta = 1\nsnapshot_periods = 3\n", "a.toml") ==
        "wrong type for 'snapshot_periods' in [bright] at a.toml:8: expected an array of finite numbers >= 0 (a "
        "TOML number, or a number string such as \"1/3\" or \"3*pi/5\"); got the integer 3");
  CHECK(load_error("experiment = \"bright\"\nmodel = 3\n[bright]\ntheta = 1\n", "a.toml") ==
        "wrong type for 'model' in the top-level table at a.toml:2: expected a table [model]; got the integer 3");
}

TEST_CASE("config: values out of range, NaN and inf name the key and the allowed range") {
  CHECK(load_error(drive_head + "amplitude = inf\n", "exp6.toml") ==
        "invalid value for 'amplitude' in [drive] at exp6.toml:4: expected a finite number in (0, 10]; got inf");
  CHECK(load_error(drive_head + "switch_off_time = nan\n", "exp6.toml") ==
        "invalid value for 'switch_off_time' in [drive] at exp6.toml:4: expected a finite number >= 0; got nan");
  CHECK(load_error(drive_head + "t_end = \"1e400\"\n", "exp6.toml") ==
        "invalid value for 't_end' in [drive] at exp6.toml:4: expected a finite number > 0; got \"1e400\"");
  CHECK(load_error(modulated_head + "epsilon = -inf\n", "exp7.toml") ==
        "invalid value for 'epsilon' in [modulated] at exp7.toml:4: expected a finite number in (0, 1]; got -inf");
  CHECK(load_error(modulated_head + "modulation_depth = 1\n", "exp7.toml") ==
        "invalid value for 'modulation_depth' in [modulated] at exp7.toml:4: expected a finite number in [0, 1); got 1");
  CHECK(load_error(drive_head + "snapshot_times = [1, -2]\n", "exp6.toml") ==
        "invalid value for 'snapshot_times' in [drive] at exp6.toml:4: element 2: expected an array of finite "
        "numbers >= 0; got -2");
  CHECK(load_error(bright_head + "[bright]\ntheta = \"pi/\"\n", "a.toml") ==
        "invalid value for 'theta' in [bright] at a.toml:7: expected a finite number; got \"pi/\"");
  // The stepper of a driven (non-autonomous) chain: adaptive ones only; a near miss is named.
  CHECK(load_error(drive_head + "[integrator]\nstepper = \"srkn11b\"\n", "exp6.toml") ==
        "invalid value for 'stepper' in [integrator] at exp6.toml:5: expected one of \"rkf78\", \"dopri5\"; got "
        "\"srkn11b\"");
  CHECK(load_error(bright_head + "[bright]\ntheta = 1\n[integrator]\nstepper = \"dopri\"\n", "a.toml") ==
        "invalid value for 'stepper' in [integrator] at a.toml:9: expected one of \"rkf78\", \"dopri5\", "
        "\"symplectic\", \"srkn11b\", \"srkn14a\", \"ss17\"; got \"dopri\"; did you mean \"dopri5\"?");
}

TEST_CASE("config: integers go through checked_integer (1e3 is 1000 — fractions, huge values refused)") {
  // (value written, value shown): a fraction, a huge float, the largest int64
  for (const auto& [value, shown] : {std::pair<std::string, std::string>{"1.5", "1.5"}, {"1e300", "1e+300"},
                                     {"9223372036854775807", "9223372036854775807"}})
    CHECK(load_error(drive_head + "sites = " + value + "\n", "a.toml") ==
          "invalid value for 'sites' in [drive] at a.toml:4: expected an integer in [10, 50000000]; got " + shown);
  for (const char* thousand : {"1e3", "1000", "\"1e3\"", "1000.0"}) {
    const auto c = lrchain::jobs::load_drive_config(Document::from_text(drive_head + "sites = " + thousand + "\n", "a.toml"));
    CHECK(c.run.beads == 1000);
  }
}

TEST_CASE("config: [bright] sites is the odd number of strain sites 2N + 1, refused in the user's terms") {
  CHECK(load_error(bright_head + "[bright]\ntheta = 1\nsites = 3\n", "a.toml") ==
        "invalid value for 'sites' in [bright] at a.toml:8: expected an integer in [5, 2000000000000001]; got 3");
  CHECK(load_error(bright_head + "[bright]\ntheta = 1\nsites = 1000\n", "a.toml") ==
        "invalid value for 'sites' in [bright] at a.toml:8: must be an odd integer in [5, 2000000000000001]: the "
        "sites are n = -N..N, 2N + 1 of them (got 1000)");
  // sites = 2N + 1: 1001 sites are n = -500..500, however the integer is written.
  const auto half_width = [](const std::string& line) {
    return lrchain::jobs::load_experiment_config(
               Document::from_text(bright_head + "[bright]\ntheta = 1\n" + line, "a.toml")).bright.N;
  };
  CHECK(half_width("sites = 1001\n") == 500);
  CHECK(half_width("sites = \"1.001e3\"\n") == 500);
  CHECK(half_width("") == lrchain::sim::BrightRunConfig{}.N);
}

TEST_CASE("config: the old keys N, beads, t_m, b are refused, naming the new key (and the new meaning of sites)") {
  CHECK(load_error(bright_head + "[bright]\ntheta = 1\nN = 500\n", "a.toml") ==
        "key 'N' in [bright] at a.toml:8 was renamed: use 'sites', the number of strain sites 2N + 1 (the old N was "
        "the half-width)");
  CHECK(load_error(drive_head + "beads = 100\n", "d.toml") == "key 'beads' in [drive] at d.toml:4 was renamed: use 'sites'");
  CHECK(load_error(drive_head + "t_m = 100\n", "d.toml") ==
        "key 't_m' in [drive] at d.toml:4 was renamed: use 'switch_off_time'");
  CHECK(load_error(modulated_head + "N = 401\n", "m.toml") == "key 'N' in [modulated] at m.toml:4 was renamed: use 'sites'");
  CHECK(load_error(modulated_head + "b = 0.01\n", "m.toml") ==
        "key 'b' in [modulated] at m.toml:4 was renamed: use 'modulation_depth'");
}

TEST_CASE("config: missing keys and kinds") {
  CHECK(load_error(bright_head + "[bright]\nsites = 11\n", "a.toml") ==
        "missing key 'theta' in [bright] at a.toml:6: expected a finite number");
  CHECK(load_error(bright_head, "a.toml") == "missing table [bright] in a.toml");
  CHECK(load_error("name = \"x\"\n", "a.toml") ==
        "missing key 'experiment' at the top level of a.toml: expected one of \"bright\", \"drive\", \"modulated\"");
  CHECK(load_error("experiment = \"brigth\"\n", "a.toml") ==
        "invalid value for 'experiment' in the top-level table at a.toml:1: expected one of \"bright\", \"drive\", "
        "\"modulated\"; got \"brigth\"; did you mean \"bright\"?");
  // A drive file given to the bright reader names the kind instead of failing on a key.
  CHECK_THROWS_WITH_AS(lrchain::jobs::load_experiment_config(Document::from_text(drive_head, "d.toml")),
                       "config file 'd.toml' is a \"drive\" experiment; this reader takes \"bright\" only", ConfigError);
}

TEST_CASE("config: every message is one line, whatever the key or value holds") {
  const std::string message = load_error(bright_head + "\"ka\\npa\" = 1\n[bright]\ntheta = \"a\\u0001b\"\n", "a.toml");
  CHECK(message == "unknown key 'ka\\x0apa' in [model] at a.toml:6; did you mean 'kappa'?");
  const std::string value = load_error(bright_head + "[bright]\ntheta = \"a\\nb\"\n", "a.toml");
  CHECK(value == "invalid value for 'theta' in [bright] at a.toml:7: expected a finite number; got \"a\\x0ab\"");
}

TEST_CASE("config: missing, directory, empty, binary, malformed files are one located ConfigError") {
  const fs::path dir = fs::temp_directory_path() / ("lrchain-config-strict-test-" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir / "sub.toml");
  const auto write = [&](const std::string& name, const std::string& bytes) {
    std::ofstream(dir / name, std::ios::binary) << bytes;
    return (dir / name).string();
  };
  const std::string missing = (dir / "none.toml").string(), sub = (dir / "sub.toml").string();
  const std::string empty = write("empty.toml", ""), blank = write("blank.toml", " \n\n");
  const std::string binary = write("binary.toml", std::string("experiment = 1\n\0\x01\x02", 18));
  const std::string bad = write("bad.toml", "experiment = \"bright\"\n[model\nrho = 1\n");
  CHECK_THROWS_WITH_AS(Document::from_file(missing), ("config file '" + missing + "' does not exist").c_str(), ConfigError);
  CHECK_THROWS_WITH_AS(Document::from_file(sub), ("config file '" + sub + "' is a directory, not a TOML file").c_str(),
                       ConfigError);
  CHECK_THROWS_WITH_AS(Document::from_file(empty), ("config file '" + empty + "' is empty").c_str(), ConfigError);
  CHECK_THROWS_WITH_AS(Document::from_file(blank), ("config file '" + blank + "' is empty").c_str(), ConfigError);
  CHECK_THROWS_WITH_AS(Document::from_file(binary),
                       ("config file '" + binary + "' is not a text file (NUL byte at line 2)").c_str(), ConfigError);
  try {
    Document::from_file(bad);
    FAIL("malformed TOML accepted");
  } catch (const ConfigError& e) {
    const std::string m = e.what();
    CHECK(m.rfind("malformed TOML in " + bad + ":2: ", 0) == 0);
    CHECK(m.find('\n') == std::string::npos);
    CHECK(e.line() == 2);
  }
  // The same through the readers used by `simulate --config`.
  CHECK_THROWS_AS(lrchain::jobs::experiment_kind(fs::path(empty)), ConfigError);
  CHECK_THROWS_AS(lrchain::jobs::load_drive_config(fs::path(sub)), ConfigError);
  fs::remove_all(dir);
}

TEST_CASE("config: the shipped examples load to the values written in them") {
  using lrchain::sim::StepperKind;
  const double pi = std::numbers::pi;
  // exp1_optical_pi2.toml: rho = "1/3", delta0 = "4/9", theta = "pi/2", N = 500, srkn11b, dt = 0.37.
  const auto e1 = lrchain::jobs::load_experiment_config(example("exp1_optical_pi2.toml"));
  CHECK(e1.experiment == "bright");
  CHECK(e1.name == "exp1-optical-theta-pi-2");
  CHECK(e1.bright.params.rho == doctest::Approx(1.0 / 3.0).epsilon(1e-15));
  CHECK(e1.bright.params.delta0 == doctest::Approx(4.0 / 9.0).epsilon(1e-15));
  CHECK(e1.bright.params.alpha == 1.5);
  CHECK(e1.bright.theta == doctest::Approx(pi / 2).epsilon(1e-15));
  CHECK(e1.bright.N == 500);
  CHECK(e1.bright.periods == 200);
  CHECK(e1.bright.snapshot_periods == std::vector<double>{0.0, 50.125, 200.0});
  CHECK(e1.bright.integrator.stepper == StepperKind::srkn11b);
  CHECK(e1.bright.integrator.dt == 0.37);
  CHECK(e1.out_dir == "out/exp1");
  // exp2: error_window_end = 150, rkf78 at 1e-12; exp3: theta = "3*pi/5", N = 1000.
  const auto e2 = lrchain::jobs::load_experiment_config(example("exp2_optical_pi8.toml"));
  CHECK(e2.bright.error_window_end == 150);
  CHECK(e2.bright.integrator.stepper == StepperKind::rkf78);
  CHECK(e2.bright.integrator.abs_tol == 1e-12);
  const auto e3 = lrchain::jobs::load_experiment_config(example("exp3_optical_3pi5.toml"));
  CHECK(e3.bright.theta == doctest::Approx(3 * pi / 5).epsilon(1e-15));
  CHECK(e3.bright.N == 1000);
  // exp4: acoustic, theta = 1.948, trailing_fit_start = 500; exp4c: ansatz_ends = true.
  const auto e4 = lrchain::jobs::load_experiment_config(example("exp4_acoustic_1948.toml"));
  CHECK(e4.bright.branch == lrchain::Branch::acoustic);
  CHECK(e4.bright.theta == 1.948);
  CHECK(e4.bright.trailing.fit_start == 500);
  CHECK(lrchain::jobs::load_experiment_config(example("exp4c_acoustic_187_emitting.toml")).bright.ansatz_ends);
  CHECK(lrchain::jobs::load_experiment_config(example("exp5_optical_rho10_123.toml")).bright.params.rho == 10);
  // exp6: drive, beads = 2000, amplitude = 0.06, t_m = 700, snapshot_times = [779.9, 2400.0], 1e-10.
  const auto e6 = lrchain::jobs::load_drive_config(example("exp6_drive_rho10.toml"));
  CHECK(e6.name == "exp6-drive-rho10");
  CHECK(e6.run.beads == 2000);
  CHECK(e6.run.amplitude == 0.06);
  CHECK(e6.run.t_m == 700);
  CHECK(e6.run.snapshot_times == std::vector<double>{779.9, 2400.0});
  CHECK(e6.run.integrator.abs_tol == 1e-10);
  CHECK(e6.out_dir == "out/exp6");
  // exp7: modulated, N = 401, delta0 = 0.27, epsilon = 0.03, checkpoint_every = 1000, symplectic.
  const auto e7 = lrchain::jobs::load_modulated_config(example("exp7_modulated_dark.toml"));
  CHECK(e7.run.N == 401);
  CHECK(e7.run.params.delta0 == 0.27);
  CHECK(e7.run.epsilon == 0.03);
  CHECK(e7.run.dark_window == 9);
  CHECK(e7.run.checkpoint_every == 1000);
  CHECK(e7.run.integrator.stepper == StepperKind::symplectic);
  // Every shipped config passes its schema.
  int loaded = 0;
  for (const auto& entry : fs::directory_iterator(fs::path(LRCHAIN_SOURCE_DIR) / "examples")) {
    if (entry.path().extension() != ".toml") continue;
    INFO(entry.path().string());
    CHECK(load_error(slurp(entry.path()), entry.path().filename().string()) == "");
    ++loaded;
  }
  CHECK(loaded == 9);
}

TEST_CASE("config: closest_match finds typos only") {
  using lrchain::config::closest_match;
  const std::vector<std::string> keys{"rho", "kappa", "delta0", "alpha"};
  CHECK(closest_match("kapa", keys) == "kappa");
  CHECK(closest_match("KAPPA", keys) == "kappa");
  CHECK(closest_match("detla0", keys) == "delta0");  // transposition
  CHECK(closest_match("beta", keys) == "");
  CHECK(closest_match("x", {"N"}) == "");
  CHECK(closest_match("n", {"N"}) == "N");
}

TEST_CASE("config: simulate --config with a bad file exits 2 with one line and writes nothing") {
  const fs::path dir = fs::temp_directory_path() / ("lrchain-config-cli-test-" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  const fs::path out = dir / "out";
  struct Case {
    std::string file, text, message;
  };
  const std::vector<Case> cases{
      {"kapa.toml", bright_head + "kapa = 5\n[bright]\ntheta = 1\n[output]\ndir = \"" + out.string() + "\"\n",
       "unknown key 'kapa' in [model] at " + (dir / "kapa.toml").string() + ":6; did you mean 'kappa'?"},
      {"amp.toml", drive_head + "amplitude = inf\n[output]\ndir = \"" + out.string() + "\"\n",
       "invalid value for 'amplitude' in [drive] at " + (dir / "amp.toml").string() +
           ":4: expected a finite number in (0, 10]; got inf"},
      {"eps.toml", modulated_head + "epsilon = nan\n[output]\ndir = \"" + out.string() + "\"\n",
       "invalid value for 'epsilon' in [modulated] at " + (dir / "eps.toml").string() +
           ":4: expected a finite number in (0, 1]; got nan"},
      {"empty.toml", "", "config file '" + (dir / "empty.toml").string() + "' is empty"},
  };
  for (const auto& c : cases) {
    INFO(c.file);
    std::ofstream(dir / c.file) << c.text;
    lrchain::ProcessOptions o;
    o.capture_stdout = o.capture_stderr = true;
    o.working_directory = dir;
    const auto r = lrchain::run_program({LRCHAIN_CLI, "simulate", "--config", (dir / c.file).string()}, o);
    CHECK(r.exit_code == 2);
    CHECK(r.output.empty());
    CHECK(r.error_output.find(c.message) != std::string::npos);
    CHECK(std::count(r.error_output.begin(), r.error_output.end(), '\n') == 1);
    CHECK_FALSE(fs::exists(out));
  }
  for (const auto& missing : {(dir / "none.toml").string(), dir.string()}) {
    lrchain::ProcessOptions o;
    o.capture_stderr = true;
    const auto r = lrchain::run_program({LRCHAIN_CLI, "simulate", "--config", missing}, o);
    CHECK(r.exit_code == 2);
    CHECK(r.error_output.find("config file '" + missing + "'") != std::string::npos);
  }
  fs::remove_all(dir);
}

TEST_CASE("config: docs/configs.md lists every key of the schema (generated part up to date)") {
  const std::string doc = slurp(fs::path(LRCHAIN_SOURCE_DIR) / "docs" / "configs.md");
  const std::string begin = "<!-- generated from the schema: begin -->\n", end = "<!-- generated from the schema: end -->";
  const auto b = doc.find(begin), e = doc.find(end);
  REQUIRE(b != std::string::npos);
  REQUIRE(e != std::string::npos);
  const std::string generated = lrchain::jobs::experiment_configs_markdown();
  const bool same = doc.substr(b + begin.size(), e - b - begin.size()) == generated;
  if (!same) std::ofstream("configs.generated.md") << generated;  // in the test's working directory
  CHECK_MESSAGE(same, "docs/configs.md is out of date with the schema: the expected text is in "
                          "configs.generated.md in the test's working directory");
}

TEST_CASE("config: a schema with sub-tables, arrays of tables and user-named keys (model files, sweeps)") {
  using namespace lrchain::config;
  // A model-file-like schema: [[fields]] entries, and [parameters] whose keys the user names.
  const auto field = std::make_shared<const TableSchema>(
      TableSchema{"one field", {string("name", "", "field name").require(), number("mass", NumberRange::positive(), "1", "")},
                  std::nullopt});
  const auto parameter = std::make_shared<const TableSchema>(TableSchema{
      "one parameter", {number("default", NumberRange::any(), "", "").require(), numbers("range", NumberRange::any(), "", "")},
      std::nullopt});
  KeySchema any_parameter = table("parameter", parameter);
  const auto parameters = std::make_shared<const TableSchema>(TableSchema{"the parameters", {}, any_parameter});
  const TableSchema root{"a model",
                         {string("model", "", "").require(), strings("tags", "[]", ""), tables("fields", field),
                          table("parameters", parameters), boolean("on_site", "false", "")},
                         std::nullopt};
  const std::string text =
      "model = \"fpu\"\n"                       // 1
      "tags = [\"a\", \"b\"]\n"                 // 2
      "[[fields]]\n"                            // 3
      "name = \"u\"\n"                          // 4
      "[[fields]]\n"                            // 5
      "name = \"v\"\n"                          // 6
      "mass = \"1/3\"\n"                        // 7
      "[parameters.beta]\n"                     // 8
      "default = 0.5\n"                         // 9
      "range = [0, \"pi\"]\n";                  // 10
  const Document doc = Document::from_text(text, "fpu.toml");
  const CheckedTable model = check(doc, root);
  std::vector<std::string> tags;
  CHECK(model.read("tags", tags));
  CHECK(tags == std::vector<std::string>{"a", "b"});
  const auto fields = model.tables("fields");
  REQUIRE(fields.size() == 2);
  std::string name;
  CHECK(fields[1].read("name", name));
  CHECK(name == "v");
  CHECK(fields[1].number("mass").value() == doctest::Approx(1.0 / 3.0).epsilon(1e-15));
  CHECK_FALSE(fields[0].number("mass").has_value());
  CHECK(fields[1].path() == "fields[2]");
  const auto params = model.table("parameters");
  REQUIRE(params);
  CHECK(params->keys() == std::vector<std::string>{"beta"});
  const auto beta = params->table("beta");
  REQUIRE(beta);
  CHECK(beta->number("default").value() == 0.5);
  CHECK(beta->line("default") == 9);
  std::vector<double> range;
  CHECK(beta->read("range", range));
  CHECK(range[1] == doctest::Approx(std::numbers::pi).epsilon(1e-15));
  bool on_site = true;
  CHECK_FALSE(model.read("on_site", on_site));  // absent: the default stays
  CHECK(on_site);
  // Reading a key the schema does not list is a programming error, not an InputError.
  CHECK_THROWS_AS(model.read("modle", name), std::logic_error);
  // Problems inside the nested tables are located the same way.
  const auto error = [&](const std::string& t) -> std::string {
    try {
      check(Document::from_text(t, "fpu.toml"), root);
    } catch (const ConfigError& e) {
      return e.what();
    }
    return "";
  };
  CHECK(error("model = \"x\"\n[[fields]]\nname = \"u\"\nmas = 2\n") ==
        "unknown key 'mas' in [fields[1]] at fpu.toml:4; did you mean 'mass'?");
  CHECK(error("model = \"x\"\n[[fields]]\nmass = 2\n") ==
        "missing key 'name' in [fields[1]] at fpu.toml:2: expected a string");
  CHECK(error("model = \"x\"\n[parameters.beta]\ndefault = inf\n") ==
        "invalid value for 'default' in [parameters.beta] at fpu.toml:3: expected a finite number; got inf");
  CHECK(error("model = \"x\"\ntags = [\"a\", 1]\n") ==
        "wrong type for 'tags' in the top-level table at fpu.toml:2: element 2: expected an array of strings; got "
        "the integer 1");
  CHECK(error("model = \"x\"\nfields = 3\n") ==
        "wrong type for 'fields' in the top-level table at fpu.toml:2: expected an array of tables [[fields]]; got "
        "the integer 3");
}

TEST_CASE("config: non-ASCII where toml++ 3.3 would reach undefined behaviour is refused — elsewhere it is kept") {
  // Found by the config fuzzer: U+FCFF (bytes EF B3 BF) outside a string made toml++ 3.3.0 reach
  // __builtin_unreachable in is_non_ascii_horizontal_whitespace (upstream issues #190, #295).
  const auto error = [](const std::string& text) -> std::string {
    try {
      Document::from_text(text, "u.toml");
    } catch (const ConfigError& e) {
      return e.what();
    }
    return "";
  };
  const std::string hint = " (write it as a \\uXXXX escape inside a \"string\")";
  const std::string in_string = "non-ASCII character in a string that is not a key = \"value\"";
  CHECK(error("\xEF\xB3\xBF") == "malformed TOML in u.toml:1: non-ASCII character outside a string or comment" + hint);
  CHECK(error("a = 1\n\xC3\xA9 = 2\n") == "malformed TOML in u.toml:2: non-ASCII character outside a string or comment" + hint);
  CHECK(error("s = \"\"\"\\\n\xC2\xA7\"\"\"\n") ==  // upstream issue #190's example
        "malformed TOML in u.toml:2: non-ASCII character first on a line continued by a backslash" + hint);
  // The fuzzer's second finding: a quote inside a malformed value does not open a string.
  CHECK(error("# [modulated]\n\nperrE=571'\xD3\x8E\xCD\x94") == "malformed TOML in u.toml:3: " + in_string + hint);
  // The third: quotes after a malformed value's braces ("05{{...{\"\"\"") do not open a string either.
  CHECK(error("a_= 05{{rho{{8{{{\"\"\"{{\xEF\xB5\xBF{{_f{") == "malformed TOML in u.toml:1: " + in_string + hint);
  CHECK(error("x = 1.\"\xC3\xA9\"\n") == "malformed TOML in u.toml:1: " + in_string + hint);
  // The fourth: a second '=' ("l=1=\"::<U+FCFF>}").
  CHECK(error("l=1=\"::\xEF\xB3\xBF}") == "malformed TOML in u.toml:1: " + in_string + hint);
  CHECK(error("a = [\n  \"\xC3\xA9\",\n]\n") == "malformed TOML in u.toml:2: " + in_string + hint);
  CHECK(error("s = \"a\\\xC3\xA9\"\n") == "malformed TOML in u.toml:1: non-ASCII character right after a backslash" + hint);
  // Inside strings and comments non-ASCII text is fine, and a byte order mark may start the file.
  const Document ok = Document::from_text(
      "\xEF\xBB\xBF# \xCF\x89 = 2.1 (omega)\nname = \"\xC3\xA9t\xC3\xA9\"\nl = '\xCF\x89'\nm = \"\"\"\n\xCF\x89\"\"\"\"\nn = 1\n",
      "u.toml");
  CHECK(ok.root()["name"].value<std::string>().value() == "\xC3\xA9t\xC3\xA9");
  CHECK(ok.root()["m"].value<std::string>().value() == "\xCF\x89\"");
  CHECK(ok.root()["n"].value<long>().value() == 1);
}

TEST_CASE("config: a renamed key is an error naming its new name, with file and line") {
  using namespace lrchain::config;
  const auto dark = std::make_shared<const TableSchema>(TableSchema{
      "a dark job", {choice("branch", {"optical", "acoustic"}, "optical", "")}, std::nullopt, {{"edge", "branch"}}});
  const TableSchema root{"a study", {table("dark", dark)}, std::nullopt};
  const auto message = [&](const std::string& text) {
    try {
      check(Document::from_text(text, "s.toml"), root);
    } catch (const ConfigError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  CHECK(message("[dark]\nedge = \"optical\"\n") == "key 'edge' in [dark] at s.toml:2 was renamed: use 'branch'");
  CHECK(message("[dark]\nbranch = \"acoustic\"\n") == "no error");
  // A renamed key is not offered as a guess for a typo of another key.
  CHECK(message("[dark]\nbranh = \"acoustic\"\n") == "unknown key 'branh' in [dark] at s.toml:2; did you mean 'branch'?");
}

TEST_CASE("config: a renamed key whose meaning changed says so after the new name") {
  using namespace lrchain::config;
  const auto lattice = std::make_shared<const TableSchema>(TableSchema{
      "a lattice", {integer("sites", 5, 99, "11", "")}, std::nullopt, {{"N", "sites", "the number of sites 2N + 1"}}});
  const TableSchema root{"a run", {table("lattice", lattice)}, std::nullopt};
  try {
    check(Document::from_text("[lattice]\n\nN = 5\n", "r.toml"), root);
    FAIL("the old key was accepted");
  } catch (const ConfigError& e) {
    CHECK(std::string(e.what()) == "key 'N' in [lattice] at r.toml:3 was renamed: use 'sites', the number of sites 2N + 1");
    CHECK(e.key() == "N");
  }
}
