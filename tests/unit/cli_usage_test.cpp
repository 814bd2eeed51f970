// How the CLI treats a new user's slips: a misspelled option or subcommand is named with the
// closest valid name, options that would do nothing are refused, every subcommand's --help lists
// the options it takes, and numbers in list and integer options go through the number parser.
// Every refusal: exit 2, one stderr line, nothing on stdout, nothing written (the job runs in an
// empty scratch directory whose listing is checked afterwards).
#include <doctest/doctest.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "../support/run_lrchain.hpp"

namespace fs = std::filesystem;

namespace {

using lrchain::test::run_lrchain;
using lrchain::test::words;

// Runs `lrchain <command>` in an empty scratch directory and checks the refusal: exit 2, exactly
// the line `message` on stderr (or, when `whole` is false, one line containing it), empty stdout,
// the directory still empty.
void check_refused(const std::string& command, const std::string& message, bool whole = true) {
  static int counter = 0;
  const fs::path dir = fs::temp_directory_path() /
                       ("lrchain-usage-" + std::to_string(::getpid()) + "-" + std::to_string(counter++));
  fs::remove_all(dir);
  fs::create_directories(dir);
  INFO("lrchain " << command);
  const auto r = run_lrchain(words(command), dir);
  INFO("stderr: " << r.err);
  CHECK(r.exit_code == 2);
  CHECK(std::count(r.err.begin(), r.err.end(), '\n') == 1);
  if (whole) CHECK(r.err == message + "\n");
  else CHECK(r.err.find(message) != std::string::npos);
  CHECK(r.out.empty());
  CHECK(fs::is_empty(dir));
  fs::remove_all(dir);
}

bool derive_is_built() { return run_lrchain({"--help"}).out.find("\n  derive ") != std::string::npos; }

}  // namespace

TEST_CASE("a misspelled option is named with the closest option, before any 'is required'") {
  check_refused("simulate bright --brnach optical",
                "lrchain simulate bright: unknown option --brnach; did you mean --branch?");
  check_refused("dark solve --omega_b 2.42", "lrchain dark solve: unknown option --omega_b; did you mean --omega-b?");
  check_refused("regime map --ot X", "lrchain regime map: unknown option --ot; did you mean --out?");
  check_refused("sweep --cofig x", "lrchain sweep: unknown option --cofig; did you mean --config?");
  check_refused("coeffs --thta=pi/2 --branch optical", "lrchain coeffs: unknown option --thta; did you mean --theta?");
  if (derive_is_built())
    check_refused("derive --modle x", "lrchain derive: unknown option --modle; did you mean --model?");
  // Also where the value of another option is refused while the command line is read.
  check_refused("simulate bright --branch optical --theta pi/2 --sites 1.5 --peroids 2",
                "lrchain simulate bright: unknown option --peroids; did you mean --periods?");
  // No valid option near it: the help is named instead.
  check_refused("coeffs --xyzzy 1", "lrchain coeffs: unknown option --xyzzy (see lrchain coeffs --help)");
}

TEST_CASE("a misspelled subcommand is named with the closest subcommand, and a stray value is named") {
  check_refused("simulat bright", "lrchain: unknown subcommand 'simulat'; did you mean simulate?");
  check_refused("dark sovle", "lrchain dark: unknown subcommand 'sovle'; did you mean solve?");
  check_refused("regime xyz", "lrchain regime: unknown subcommand 'xyz'; give one of: intervals, map, thresholds "
                              "(see lrchain regime --help)");
  check_refused("coeffs --branch optical --theta pi/2 3", "lrchain coeffs: unexpected argument '3'", false);
}

TEST_CASE("every simulate subcommand's --help lists the output options it takes, with defaults") {
  for (const char* sub : {"bright", "drive", "modulated", "ring"}) {
    const auto r = run_lrchain({"simulate", sub, "--help"});
    INFO("lrchain simulate " << sub << " --help");
    REQUIRE(r.exit_code == 0);
    for (const char* option : {"--out DIR", "--json", "--no-figures", "--figure-format", "--format csv|hdf5"})
      CHECK(r.out.find("\n  " + std::string(option)) != std::string::npos);
    const bool lattice_run = std::string(sub) != "ring";  // ring has no checkpoints
    for (const char* option : {"--restart FILE", "--checkpoint FILE", "--max-memory SIZE"})
      CHECK((r.out.find("\n  " + std::string(option)) != std::string::npos) == lattice_run);
  }
  const auto top = run_lrchain({"simulate", "--help"});
  CHECK(top.out.find("{false}") == std::string::npos);
  CHECK(top.out.find("\n  --no-figures ") != std::string::npos);
}

TEST_CASE("options that would do nothing are refused") {
  const std::string bright = "simulate bright --branch optical --theta pi/2 --sites 21 --periods 1 ";
  const std::string needs_out = " needs --out DIR: it only changes the files written there";
  check_refused(bright + "--no-figures", "lrchain: --no-figures" + needs_out);
  check_refused(bright + "--format hdf5", "lrchain: --format" + needs_out);
  check_refused(bright + "--figure-format svg", "lrchain: --figure-format" + needs_out);
  check_refused("simulate --no-figures bright --branch optical --theta pi/2", "lrchain: --no-figures" + needs_out);
  check_refused("dark solve --omega-b 2.42 --format hdf5", "lrchain: --format" + needs_out);
  check_refused("dark solve --omega-b 2.42 --figure-format svg", "lrchain: --figure-format" + needs_out);
  check_refused("simulate --config x.toml bright --branch optical --theta pi/2",
                "lrchain: --config runs the experiment in its file; give it without the subcommand bright");
  check_refused("coeffs --table --theta pi/2 --branch optical",
                "lrchain: --theta is not used with --table (it lists every branch at theta = pi/8 ... pi)");
  check_refused("regime map --plane theta-rho --delta0-range 0.1 1 --out map",
                "lrchain: --delta0-range belongs to --plane delta0-omega; the theta-rho plane takes --rho-range");
  check_refused("regime map --plane delta0-omega --rho-range 0.1 1 --out map",
                "lrchain: --rho-range belongs to --plane theta-rho; the delta0-omega plane takes --delta0-range and "
                "--omega-range");
  // One name for one concept: regime map draws its figures unless --no-figures, like simulate.
  check_refused("regime map --no-png --out map", "lrchain regime map: unknown option --no-png", false);
}

TEST_CASE("coeffs --table --json holds every branch's rows, the same numbers as coeffs at one wavenumber") {
  const auto table = run_lrchain({"coeffs", "--table", "--json", "--rho", "1/3"});
  REQUIRE(table.exit_code == 0);
  const auto j = nlohmann::json::parse(table.out);
  REQUIRE(j["branches"].size() == 2);
  CHECK(j["branches"][0]["branch"] == "optical");
  CHECK(j["branches"][1]["branch"] == "acoustic");
  for (const auto& b : j["branches"]) CHECK(b["rows"].size() == 6);  // pi/8, pi/4, pi/2, 3pi/5, 3pi/4, pi
  const auto& row = j["branches"][0]["rows"][2];
  CHECK(row["theta_label"] == "pi/2");
  // Expected: the single-wavenumber command, which evaluates the same coefficients.
  const auto one = run_lrchain({"coeffs", "--branch", "optical", "--theta", "pi/2", "--rho", "1/3", "--json"});
  REQUIRE(one.exit_code == 0);
  const auto c = nlohmann::json::parse(one.out);
  for (const char* key : {"omega", "group_velocity", "curvature", "h", "h_tilde"})
    CHECK(row[key].get<double>() == doctest::Approx(c[key].get<double>()).epsilon(1e-14));
  CHECK(row["regime"] == c["regime"]);
}

TEST_CASE("list and integer options take every number syntax, and an overflow guard is not shown as a bound") {
  // pi reaches the run's check as 3.14159...: outside a 3-period run, so refused naming the value.
  check_refused("simulate bright --branch optical --theta pi/2 --sites 21 --periods 3 --snapshots 0 pi",
                "snapshot time 3.141592653589793 T_b", false);
  check_refused("simulate drive --sites 50 --t-end 2 --snapshots 1 3*pi", "snapshot time", false);
  const auto list = run_lrchain({"reproduce", "--jobs", "1e0", "--list"});
  CHECK(list.exit_code == 0);
  CHECK(list.out.find("coefficients") != std::string::npos);
  check_refused("simulate bright --branch optical --theta pi/2 --sites 1001.5",
                "lrchain: invalid sites: must be an odd integer: the sites are n = -N..N, 2N + 1 of them");
  // The range that applies: the resonant chain's [5, ...], a model file's [21, ...].
  check_refused("simulate bright --branch optical --theta pi/2 --sites 3",
                "lrchain: invalid sites: must be an odd integer in [5, 2000000000000001]: the sites are n = -N..N, "
                "2N + 1 of them (got 3)");
  check_refused("simulate bright --model fput --branch acoustic --theta pi/2 --sites 22",
                "lrchain: invalid sites: must be an odd integer in [21, 100000001]: the sites are n = -N..N, "
                "2N + 1 of them (got 22)");
  check_refused("dark solve --omega-b 2.42 --sites 8.5", "lrchain: invalid sites: must be an integer >= 9");
  check_refused("reproduce --jobs 65", "lrchain: invalid jobs: must be an integer in [0, 64]");
}

TEST_CASE("every dark subcommand's help ends with its examples and the exit codes") {
  for (const char* sub : {"solve", "floquet", "continue", "evolve"}) {
    const auto r = run_lrchain({"dark", sub, "--help"});
    INFO("lrchain dark " << sub << " --help");
    REQUIRE(r.exit_code == 0);
    CHECK(r.out.find("Exit codes: 0 success") != std::string::npos);
    const auto examples = r.out.find("Example");
    REQUIRE(examples != std::string::npos);
    // "Examples:" above two or more command lines, "Example:" above one.
    const std::string after = r.out.substr(examples);
    long commands = 0;
    for (std::size_t at = 0; (at = after.find("\n  lrchain dark " + std::string(sub), at)) != std::string::npos; ++at)
      ++commands;
    CHECK(commands >= 1);
    CHECK((after.rfind("Examples:", 0) == 0) == (commands > 1));
  }
}

TEST_CASE("--model NAME is a shipped model by its name, and an unknown name lists the shipped models") {
  // Expected: the same model given as its file in the source tree (this lrchain runs from its build
  // tree, so NAME resolves to that file).
  const auto by_name = run_lrchain(words("coeffs --model klein_gordon --branch branch0 --theta pi/2 --json"));
  const auto by_file = run_lrchain({"coeffs", "--model", LRCHAIN_SOURCE_DIR "/models/klein_gordon.toml", "--branch",
                                    "branch0", "--theta", "pi/2", "--json"});
  REQUIRE(by_name.exit_code == 0);
  REQUIRE(by_file.exit_code == 0);
  const auto a = nlohmann::json::parse(by_name.out), b = nlohmann::json::parse(by_file.out);
  CHECK(a["model"]["name"] == "klein_gordon");
  CHECK(a["omega"].get<double>() == b["omega"].get<double>());
  CHECK(a["h"].get<double>() == b["h"].get<double>());
  check_refused("coeffs --model klein_gordn --branch branch0 --theta pi/2",
                "lrchain: --model klein_gordn: no such file or shipped model; the shipped models are ", false);
  const auto r = run_lrchain(words("coeffs --model klein_gordn --branch branch0 --theta pi/2"));
  for (const char* name : {"diatomic_chain", "fput", "klein_gordon", "resonant_chain"})
    CHECK(r.err.find(name) != std::string::npos);
}
