// The CLI on big numbers, jobs too large for the machine, numerical failures and the small input
// rules: exit 2 within seconds with the option named and nothing written, exit 3 on a blow-up with
// the failure in the JSON, integral values such as 1e3 for integer options, null for "none".
// Every job runs through lrchain::run_program in a fresh working directory whose listing is
// compared before and after.
#include <doctest/doctest.h>

#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <set>
#include <string>
#include <vector>

#include "lrchain/process.hpp"

namespace fs = std::filesystem;

namespace {

struct Job {
  int exit_code = -1;
  std::string out, err;
  double seconds = 0;
  std::set<std::string> created;  // paths (relative) that did not exist before the job
};

std::set<std::string> listing(const fs::path& dir) {
  std::set<std::string> names;
  for (const auto& e : fs::recursive_directory_iterator(dir)) names.insert(fs::relative(e.path(), dir).string());
  return names;
}

// Runs `lrchain args...` in a fresh directory (holding `files`: name -> content, written first).
Job run_lrchain(const std::vector<std::string>& args,
                const std::vector<std::pair<std::string, std::string>>& files = {}) {
  static int counter = 0;
  const fs::path dir = fs::temp_directory_path() /
                       ("lrchain-limits-" + std::to_string(::getpid()) + "-" + std::to_string(counter++));
  fs::remove_all(dir);
  fs::create_directories(dir);
  for (const auto& [name, content] : files) std::ofstream(dir / name) << content;
  const auto before = listing(dir);
  lrchain::ProcessOptions o;
  o.working_directory = dir;
  o.capture_stdout = o.capture_stderr = true;
  std::vector<std::string> argv{LRCHAIN_CLI};
  argv.insert(argv.end(), args.begin(), args.end());
  const auto t0 = std::chrono::steady_clock::now();
  const auto r = lrchain::run_program(argv, o);
  Job job;
  job.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  job.exit_code = r.exited ? r.exit_code : 128 + r.signal_number;
  job.out = r.output;
  job.err = r.error_output;
  for (const auto& name : listing(dir))
    if (!before.count(name)) job.created.insert(name);
  fs::remove_all(dir);
  return job;
}

// Exit 2 within a few seconds, one line on stderr naming `option`, nothing written.
void check_refused(const std::vector<std::string>& args, const std::string& option,
                   const std::vector<std::pair<std::string, std::string>>& files = {}) {
  std::string line;
  for (const auto& a : args) line += a + " ";
  INFO("lrchain " << line);
  const Job j = run_lrchain(args, files);
  INFO("stderr: " << j.err);
  CHECK(j.exit_code == 2);
  CHECK(j.seconds < 5.0);
  CHECK(j.err.find(option) != std::string::npos);
  CHECK(std::count(j.err.begin(), j.err.end(), '\n') == 1);
  CHECK(j.created.empty());
}

const std::vector<std::string> bright = {"simulate", "bright", "--branch", "optical", "--theta", "pi/2"};

std::vector<std::string> with(std::vector<std::string> base, const std::vector<std::string>& more) {
  base.insert(base.end(), more.begin(), more.end());
  return base;
}

}  // namespace

TEST_CASE("big numbers that crashed (overflowing float-to-integer casts) are exit 2") {
  // Before: segmentation faults (sample count overflow, then times.back() of an empty vector).
  check_refused(with(bright, {"--periods", "1e300pi", "--out", "o"}), "periods");
  check_refused({"simulate", "drive", "--t-end", "1e308pi", "--out", "o"}, "t-end");
  check_refused({"simulate", "drive", "--t-end", "inf", "--out", "o"}, "t-end");
  check_refused({"simulate", "modulated", "--t-end", "1e300", "--out", "o"}, "t-end / sample-every");
  // Before: dt = 1e-300 overflowed the step count of srkn11b (16 steps taken instead of 32, exit 0).
  check_refused(with(bright, {"--stepper", "srkn11b", "--dt", "1e-300", "--periods", "1", "--out", "o"}), "dt");
  check_refused({"dark", "evolve", "--omega-b", "2.0", "--t-end", "1e300", "--out", "o"}, "t-end");
  check_refused({"dark", "evolve", "--omega-b", "2.0", "--t-end", "nan", "--out", "o"}, "t-end");
}

TEST_CASE("a t_end of inf in a config file is exit 2 with nothing written") {
  std::ifstream in(std::string(LRCHAIN_SOURCE_DIR) + "/examples/exp6_drive_rho10.toml");
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const auto at = text.find("t_end = 2400");
  REQUIRE(at != std::string::npos);
  text.replace(at, 12, "t_end = inf");
  check_refused({"simulate", "--config", "drive.toml", "--out", "o"}, "t", {{"drive.toml", text}});
}

TEST_CASE("jobs larger than the machine are refused before any allocation, naming the option") {
  // Each of these allocated until std::bad_alloc or ran for minutes. The estimates are terabytes,
  // beyond any machine, except where --max-memory sets the limit.
  check_refused(with(bright, {"--sites", "2000000001", "--out", "o"}), "sites");
  check_refused(with(bright, {"--periods", "1e9", "--out", "o"}), "periods");
  check_refused(with(bright, {"--periods", "1", "--sample-every", "1e-9", "--out", "o"}), "sample-every");
  check_refused(with(bright, {"--periods", "100", "--sample-every", "1e-6", "--spacetime-every", "1e-6",
                              "--out", "o"}),
                "spacetime-every");
  check_refused({"simulate", "drive", "--sites", "1e10", "--out", "o"}, "sites");
  check_refused({"simulate", "drive", "--t-end", "1e9", "--out", "o"}, "t-end");
  check_refused({"simulate", "modulated", "--sites", "1e9", "--out", "o"}, "sites");
  check_refused({"simulate", "modulated", "--sample-every", "1e-6", "--out", "o"}, "sample-every");
  check_refused({"simulate", "modulated", "--checkpoint-every", "1e-7", "--out", "o"}, "checkpoint-every");
  check_refused({"dark", "solve", "--omega-b", "2.0", "--sites", "1000001", "--out", "o"}, "sites");
  check_refused({"dark", "floquet", "--omega-b", "2.0", "--sites", "101", "--max-memory", "10M", "--out", "o"},
                "max-memory");
  check_refused({"dark", "evolve", "--omega-b", "2.0", "--t-end", "1e9", "--out", "o"}, "t-end");
  check_refused({"dark", "solve", "--omega-b", "1e-300", "--out", "o"}, "omega-b");
  check_refused({"regime", "map", "--nx", "20000", "--ny", "20000", "--max-memory", "1G", "--out", "o"}, "nx");
  check_refused(with(bright, {"--max-memory", "1M", "--out", "o"}), "max-memory");
  check_refused(with(bright, {"--max-memory", "lots", "--out", "o"}), "max-memory");
}

// (Beyond the end they are allowed for a run that writes a checkpoint at its end, to be continued.)
TEST_CASE("snapshot times outside the run are exit 2, not dropped") {
  check_refused(with(bright, {"--periods", "10", "--snapshots", "0", "20", "--out", "o"}), "snapshots");
  check_refused({"simulate", "drive", "--snapshots", "-1", "--out", "o"}, "snapshots");
  check_refused({"simulate", "modulated", "--t-end", "10", "--snapshots", "20", "--checkpoint-every", "0",
                 "--out", "o"},
                "snapshots");
}

TEST_CASE("regime map, modulated runs and dark continue validate everything before writing") {
  check_refused({"regime", "map", "--rho-range", "-1", "2", "--out", "o"}, "rho-range");
  check_refused({"regime", "map", "--plane", "delta0-omega", "--delta0-range", "0", "1", "--out", "o"},
                "delta0-range");
  check_refused({"simulate", "modulated", "--epsilon", "inf", "--out", "o"}, "epsilon");
  check_refused({"dark", "continue", "--omega-b", "2.4", "--points", "-1", "--out", "o"}, "points");
  check_refused({"dark", "continue", "--omega-b", "2.4", "--ds", "inf", "--out", "o"}, "ds");
}

TEST_CASE("an --out that is a file is exit 2 with the file untouched") {
  const Job j = run_lrchain(with(bright, {"--sites", "41", "--periods", "1", "--out", "taken"}), {{"taken", "user data"}});
  CHECK(j.exit_code == 2);
  CHECK(j.err.find("taken") != std::string::npos);
  CHECK(j.created.empty());
  CHECK(run_lrchain({"regime", "map", "--out", "taken"}, {{"taken", "x"}}).exit_code == 2);
  CHECK(run_lrchain({"dark", "solve", "--omega-b", "2.4", "--out", "taken"}, {{"taken", "x"}}).exit_code == 2);
}

TEST_CASE("integer options accept integral values such as 1e3 and refuse fractions") {
  // --sites 2.01e2 = 201 strain sites n = -100..100: the summary's "sites" is the value given.
  const Job j = run_lrchain(with(bright, {"--sites", "2.01e2", "--periods", "2", "--json"}));
  REQUIRE(j.exit_code == 0);
  CHECK(nlohmann::json::parse(j.out)["sites"] == 201);
  check_refused(with(bright, {"--sites", "100.5"}), "sites");
  check_refused(with(bright, {"--sites", "1e300"}), "sites");
  check_refused(with(bright, {"--sites", "200"}), "sites");  // even: not n = -N..N
  check_refused({"regime", "intervals", "--samples", "1e300"}, "samples");
}

TEST_CASE("a blown-up lattice run is exit 3, says when and where, and keeps its outputs") {
  // McLachlan's symplectic stepper with dt = 1.5 is unstable on this chain (measured: it blows up
  // at t = 90; the same run with dt = 1 stays finite to t = 200).
  const Job j = run_lrchain({"simulate", "modulated", "--sites", "16", "--theta-waves", "8", "--dt", "1.5",
                             "--t-end", "200", "--checkpoint-every", "0", "--out", "o", "--json"});
  INFO("stderr: " << j.err);
  CHECK(j.exit_code == 3);
  CHECK(j.err.find("blew up") != std::string::npos);
  CHECK(j.err.find("site") != std::string::npos);
  const auto s = nlohmann::json::parse(j.out);
  CHECK(s["blew_up"] == true);
  REQUIRE(s["failure"].is_object());
  CHECK(s["failure"]["kind"] == "blow-up");
  CHECK(s["failure"]["t"].get<double>() < 200);
  CHECK(s["failure"]["site"].get<long>() >= 0);
  CHECK(s["failure"]["site"].get<long>() < 16);
  CHECK(j.created.count("o/summary.json") == 1);
  CHECK(j.created.count("o/series.csv") == 1);
}

TEST_CASE("JSON says null for none: no instability, no dark-breather speed, no failure") {
  // Contrast threshold 10: far above the contrast of eq:cimi (about 0.1), so no instability time.
  const Job j = run_lrchain({"simulate", "modulated", "--sites", "64", "--theta-waves", "40", "--t-end", "50",
                             "--contrast-threshold", "10", "--checkpoint-every", "0", "--json"});
  REQUIRE(j.exit_code == 0);
  const auto s = nlohmann::json::parse(j.out);
  CHECK(s["instability_time"].is_null());
  CHECK(s["dark_speed"].is_null());  // its fit window [30000, 33000] lies beyond t_end = 50
  CHECK(s["failure"].is_null());
  CHECK(s["blew_up"] == false);
}

TEST_CASE("--help lists the exit codes") {
  const Job j = run_lrchain({"--help"});
  CHECK(j.exit_code == 0);
  for (const char* code : {"Exit codes", "0 success", "2 bad input", "3 numerical failure", "130/143"})
    CHECK(j.out.find(code) != std::string::npos);
}

namespace {

// Exit 2 with one stderr line naming `parameter` and showing its allowed range `range_text`.
void check_out_of_range(const std::vector<std::string>& args, const std::string& parameter,
                        const std::string& range_text,
                        const std::vector<std::pair<std::string, std::string>>& files = {}) {
  check_refused(args, parameter, files);
  const Job j = run_lrchain(args, files);
  INFO("stderr: " << j.err);
  CHECK(j.err.find(range_text) != std::string::npos);
}

// An example config with `from` replaced by `to` (one occurrence, which must exist).
std::string example_with(const std::string& file, const std::string& from, const std::string& to) {
  std::ifstream in(std::string(LRCHAIN_SOURCE_DIR) + "/examples/" + file);
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const auto at = text.find(from);
  REQUIRE(at != std::string::npos);
  return text.replace(at, from.size(), to);
}

}  // namespace

TEST_CASE("physical parameters outside their declared ranges are exit 2 naming the parameter and the range") {
  // The ranges are lrchain/params.hpp's: alpha (1, 5], delta0 (0, 10], kappa and rho (0, 10000],
  // epsilon (0, 1], the drive amplitude (0, delta0], dt at most the run's length. Before, each of
  // these ran (exit 0), blew up (exit 3) or ran past the corpus's 10 s.
  check_out_of_range(with(bright, {"--rho", "1e308", "--out", "o"}), "rho", "(0, 10000]");
  check_out_of_range(with(bright, {"--kappa", "1e300pi", "--out", "o"}), "kappa", "(0, 10000]");
  check_out_of_range(with(bright, {"--delta0", "10.5", "--out", "o"}), "delta0", "(0, 10]");
  check_out_of_range(with(bright, {"--alpha", "5.01", "--out", "o"}), "alpha", "(1, 5]");
  check_out_of_range(with(bright, {"--n0", "1e308", "--out", "o"}), "n0", "[-N, N]");
  check_out_of_range({"dark", "solve", "--omega-b", "2.42", "--rho", "1e308", "--out", "o"}, "rho", "(0, 10000]");
  check_out_of_range({"regime", "intervals", "--alpha", "1e308"}, "alpha", "(1, 5]");
  check_out_of_range({"simulate", "drive", "--amplitude", "0.5", "--out", "o"}, "amplitude", "(0, 0.444444]");
  check_out_of_range({"simulate", "drive", "--delta0", "0.05", "--out", "o"}, "amplitude", "(0, 0.05]");
  check_out_of_range({"simulate", "modulated", "--epsilon", "1.5", "--out", "o"}, "epsilon", "(0, 1]");
  check_out_of_range({"simulate", "modulated", "--t-end", "100", "--dt", "1e308", "--out", "o"}, "dt", "(0, 100]");
  check_out_of_range({"simulate", "drive", "--t-end", "100", "--dt", "200", "--out", "o"}, "dt", "(0, 100]");
  // The same ranges for the config keys, with the file and line.
  check_out_of_range({"simulate", "--config", "x.toml", "--out", "o"}, "amplitude", "x.toml:",
                     {{"x.toml", example_with("exp6_drive_rho10.toml", "amplitude = 0.06", "amplitude = 1e308")}});
  check_out_of_range({"simulate", "--config", "x.toml", "--out", "o"}, "epsilon", "(0, 1]",
                     {{"x.toml", example_with("exp7_modulated_dark.toml", "epsilon = 0.03", "epsilon = 1e308")}});
  check_out_of_range({"simulate", "--config", "x.toml", "--out", "o"}, "alpha", "x.toml:13",
                     {{"x.toml", example_with("exp7_modulated_dark.toml", "alpha = \"3/2\"", "alpha = 1e308")}});
  check_out_of_range({"simulate", "--config", "x.toml", "--out", "o"}, "amplitude", "(0, 0.444444]",
                     {{"x.toml", example_with("exp6_drive_rho10.toml", "amplitude = 0.06", "amplitude = 0.5")}});
}

TEST_CASE("the largest value of each physical parameter's range is accepted") {
  for (const auto& [option, value] : std::vector<std::pair<std::string, std::string>>{
           {"--rho", "10000"}, {"--kappa", "10000"}, {"--delta0", "10"}, {"--alpha", "5"}}) {
    const Job j = run_lrchain({"coeffs", "--theta", "pi/2", "--branch", "optical", option, value, "--json"});
    INFO(option << " " << value << ": " << j.err);
    CHECK(j.exit_code == 0);
  }
}

TEST_CASE("file options of the wrong kind are exit 2 naming the option, nothing written") {
  check_refused({"reproduce", "--only", "coefficients", "--examples", "f", "--out", "o"}, "examples", {{"f", "x"}});
  check_refused({"reproduce", "--only", "coefficients", "--errata", ".", "--out", "o"}, "errata");
  check_refused({"simulate", "modulated", "--t-end", "2", "--sample-every", "1", "--checkpoint", ".", "--out", "o"},
                "checkpoint");
}

TEST_CASE("a new run refuses an --out holding an earlier run's checkpoint — a restart from it continues") {
  const fs::path dir = fs::temp_directory_path() / ("lrchain-stale-checkpoint-" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  lrchain::ProcessOptions o;
  o.working_directory = dir;
  o.capture_stdout = o.capture_stderr = true;
  const std::vector<std::string> first = {LRCHAIN_CLI, "simulate", "modulated", "--sites", "16", "--theta-waves", "8",
                                          "--t-end", "2", "--sample-every", "1", "--checkpoint-every", "1",
                                          "--out", "o", "--json"};
  REQUIRE(lrchain::run_program(first, o).exit_code == 0);
  REQUIRE(fs::exists(dir / "o" / "checkpoint.bin"));
  const auto before = listing(dir);
  const auto again = lrchain::run_program(first, o);
  CHECK(again.exit_code == 2);
  CHECK(again.error_output.find("invalid checkpoint: 'o/checkpoint.bin' holds the checkpoint of an earlier run") !=
        std::string::npos);
  CHECK(std::count(again.error_output.begin(), again.error_output.end(), '\n') == 1);
  CHECK(listing(dir) == before);
  auto restart = first;
  restart[8] = "4";  // --t-end 4
  restart.insert(restart.end(), {"--restart", "o/checkpoint.bin"});
  const auto continued = lrchain::run_program(restart, o);
  INFO(continued.error_output);
  CHECK(continued.exit_code == 0);
  CHECK(nlohmann::json::parse(continued.output)["t_start"].get<double>() == doctest::Approx(2));
  fs::remove_all(dir);
}
