// The run checks of a simulate config (validate() of the run: theta in (0, pi], the drive amplitude
// at most delta0, omega0 in the optical band, two-key checks) name the file, line, table and key
// like the schema's own range checks ("invalid value for 'rho' in [model] at run.toml:5: ..."), in
// the library and through `lrchain simulate --config` (exit 2, one line, nothing written).
#include <doctest/doctest.h>

#include <fmt/format.h>

#include <filesystem>
#include <numbers>
#include <fstream>
#include <string>
#include <unistd.h>

#include "../support/run_lrchain.hpp"
#include "lrchain/config/strict_toml.hpp"
#include "lrchain/dispersion.hpp"
#include "lrchain/errors.hpp"
#include "lrchain/sim/drive_run.hpp"
#include "lrchain/jobs/experiment_config.hpp"
#include "lrchain/jobs/more_experiment_config.hpp"

namespace fs = std::filesystem;
using lrchain::config::ConfigError;
using lrchain::config::Document;

namespace {

// Loads `text` (named `source`) with the reader of its kind; the ConfigError it throws (an
// unlocated InvalidParameter fails the test).
ConfigError located_error(const std::string& text, const std::string& source) {
  const Document doc = Document::from_text(text, source);
  const std::string kind = lrchain::jobs::experiment_kind(doc);
  try {
    if (kind == "drive") lrchain::jobs::load_drive_config(doc);
    else lrchain::jobs::load_experiment_config(doc);
  } catch (const ConfigError& e) {
    return e;
  } catch (const lrchain::InputError& e) {
    FAIL("not located: ", e.what());
  }
  FAIL("loaded: ", text);
  return ConfigError("", "", 0, "", "");
}

const std::string bright_config =
    "experiment = \"bright\"\n"  // 1
    "[model]\n"                  // 2
    "rho = \"1/3\"\n"            // 3
    "[bright]\n"                 // 4
    "sites = 121\n";             // 5

// Exp. 6's model (the DriveRunConfig defaults: rho = 10, delta0 = 4/9).
const std::string drive_config =
    "experiment = \"drive\"\n"  // 1
    "[model]\n"                 // 2
    "delta0 = \"4/9\"\n"        // 3
    "[drive]\n"                 // 4
    "sites = 100\n";            // 5

}  // namespace

TEST_CASE("config run checks: theta, amplitude, omega0 name file:line, table and key") {
  // theta = "4" > pi (Sec. 4.1: the carrier wavenumber lies in (0, pi]).
  ConfigError e = located_error(bright_config + "theta = \"4\"\n", "cfg/theta.toml");
  CHECK(std::string(e.what()) ==
        "invalid value for 'theta' in [bright] at cfg/theta.toml:6: the carrier wavenumber must be in (0, pi]");
  CHECK(e.line() == 6);
  CHECK(e.table() == "bright");
  CHECK(e.key() == "theta");
  // amplitude 0.5 > delta0 = 4/9 (Sec. 4.3: the stroke may not exceed the precompression overlap).
  e = located_error(drive_config + "amplitude = 0.5\n", "cfg/amplitude.toml");
  CHECK(std::string(e.what()).starts_with("invalid value for 'amplitude' in [drive] at cfg/amplitude.toml:6: must be "
                                          "a finite number in (0, delta0] = (0, 0.444444"));
  CHECK(e.key() == "amplitude");
  // omega0 = 10 above the optical band's top omega_+(pi) (eq:disp1d) at exp. 6's rho = 10.
  const lrchain::Params exp6 = lrchain::sim::DriveRunConfig{}.params;
  e = located_error(drive_config + "omega0 = 10\n", "cfg/omega0.toml");
  CHECK(std::string(e.what()) ==
        fmt::format("invalid value for 'omega0' in [drive] at cfg/omega0.toml:6: must lie in the optical band "
                    "({:.6g}, {:.6g}]", lrchain::dispersion_omega(exp6, lrchain::Branch::optical, 0.0),
                    lrchain::dispersion_omega(exp6, lrchain::Branch::optical, std::numbers::pi)));
  // A two-key check (ramp_rate <= omega0) names the key as the file spells it.
  e = located_error(drive_config + "omega0 = 2.2\nramp_rate = 3\n", "cfg/ramp.toml");
  CHECK(std::string(e.what()).starts_with("invalid value for 'ramp_rate' in [drive] at cfg/ramp.toml:7: must be in (0, omega0]"));
  // A key the file does not hold (amplitude's default 0.06 against delta0 = 0.01) keeps the message
  // naming the parameter, unlocated; a valid file loads.
  CHECK_THROWS_WITH_AS(lrchain::jobs::load_drive_config(Document::from_text(
                           "experiment = \"drive\"\n[model]\ndelta0 = 0.01\n[drive]\nsites = 100\n", "d.toml")),
                       doctest::Contains("invalid amplitude: must be a finite number in (0, delta0] = (0, 0.01]"),
                       lrchain::InvalidParameter);
  CHECK_NOTHROW(lrchain::jobs::load_experiment_config(Document::from_text(bright_config + "theta = 1\n", "ok.toml")));
}

TEST_CASE("config run checks: the run's checks of sites and switch_off_time name the keys as the file spells them") {
  // 1000 strain sites: sites = 2N + 1 is odd.
  ConfigError e = located_error(bright_config.substr(0, bright_config.find("sites")) + "sites = 1000\ntheta = 1\n",
                                "cfg/sites.toml");
  CHECK(std::string(e.what()) == "invalid value for 'sites' in [bright] at cfg/sites.toml:5: must be an odd integer in "
                                 "[5, 2000000000000001]: the sites are n = -N..N, 2N + 1 of them (got 1000)");
  CHECK(e.key() == "sites");
  // A switch-off time no continuation of the run can reach (sampling_checks.cpp).
  e = located_error(drive_config + "switch_off_time = 1e12\n", "cfg/t.toml");
  CHECK(std::string(e.what()).starts_with("invalid value for 'switch_off_time' in [drive] at cfg/t.toml:6: must be at most"));
  CHECK(e.key() == "switch_off_time");
}

TEST_CASE("config run checks: `lrchain simulate --config` with theta = \"4\" exits 2 naming file:line, writes nothing") {
  const fs::path dir = fs::temp_directory_path() / ("lrchain-config-located-" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  std::ofstream(dir / "theta.toml") << bright_config << "theta = \"4\"\n[output]\ndir = \"out\"\n";
  const auto r = lrchain::test::run_lrchain({"simulate", "--config", (dir / "theta.toml").string()}, dir);
  CHECK(r.exit_code == 2);
  CHECK(r.err == "lrchain: invalid value for 'theta' in [bright] at " + (dir / "theta.toml").string() +
                     ":6: the carrier wavenumber must be in (0, pi]\n");
  CHECK_FALSE(fs::exists(dir / "out"));
  fs::remove_all(dir);
}
