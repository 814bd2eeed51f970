// SIGTERM/SIGINT during `lrchain simulate bright` (and model-file runs): exit 143/130 with the restart command on stderr,
// every file in --out complete, and the restart (exit 0) gives the uninterrupted run's files byte
// for byte (expected: the uninterrupted run itself). Also: a restart with changed physics or from a
// damaged checkpoint is exit 2 naming the cause, and writes nothing.
#include <doctest/doctest.h>

#include <signal.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <string>
#include <thread>
#include <vector>

#include "lrchain/process.hpp"
#include "lrchain/jobs/checkpoint/checkpoint_file.hpp"

namespace fs = std::filesystem;

namespace {

std::string slurp(const fs::path& f) {
  std::ifstream in(f, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

std::vector<std::string> bright_args(const fs::path& out) {
  return {LRCHAIN_CLI, "simulate", "bright", "--branch", "optical", "--theta", "pi/2", "--sites", "401",
          "--periods", "300", "--snapshots", "0", "150", "300", "--checkpoint-every", "5",
          "--out", out.string(), "--json"};
}

// Starts the run, waits for its first periodic checkpoint (it is then running), sends `signal`.
lrchain::ProcessResult interrupt_run(const fs::path& out, int signal_number) {
  lrchain::ProcessOptions o;
  o.capture_stdout = o.capture_stderr = true;
  lrchain::ChildProcess child(bright_args(out), o);
  const auto give_up = std::chrono::steady_clock::now() + std::chrono::seconds(120);
  while (!fs::exists(out / "checkpoint.bin") && std::chrono::steady_clock::now() < give_up)
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  child.send_signal(signal_number);
  return child.wait();
}

// Every file in `dir` is complete: no temporary left, JSON parses, CSV rows have the header's
// column count, the space-time matrix has whole rows, the checkpoint verifies.
void check_files_complete(const fs::path& dir) {
  int files = 0;
  for (const auto& e : fs::directory_iterator(dir)) {
    const std::string name = e.path().filename().string();
    CAPTURE(name);
    ++files;
    CHECK(name[0] != '.');  // temporary names start with a dot
    const std::string text = slurp(e.path());
    if (e.path().extension() == ".json") {
      const auto j = nlohmann::json::parse(text);
      CHECK(j["interrupted"].get<bool>());
    } else if (e.path().extension() == ".csv") {
      REQUIRE(!text.empty());
      CHECK(text.back() == '\n');
      std::size_t pos = 0, columns = 0, rows = 0;
      while (pos < text.size()) {
        const std::size_t end = text.find('\n', pos);
        const std::string line = text.substr(pos, end - pos);
        const std::size_t n = std::size_t(std::count(line.begin(), line.end(), ',')) + 1;
        if (rows == 0) columns = n;
        CHECK(n == columns);
        ++rows;
        pos = end + 1;
      }
      CHECK(rows > 1);
    } else if (name == "energy_density_spacetime.bin") {
      float sites = 0;
      std::memcpy(&sites, text.data(), sizeof sites);
      CHECK(sites == 402);  // beads -N-1..N
      CHECK(text.size() % ((std::size_t(sites) + 1) * sizeof(float)) == 0);
    } else if (name == "checkpoint.bin") {
      CHECK_NOTHROW(lrchain::jobs::read_checkpoint(e.path()));
    }
  }
  CHECK(files >= 5);
}

std::map<std::string, std::string> listing(const fs::path& dir) {
  std::map<std::string, std::string> m;
  for (const auto& e : fs::directory_iterator(dir)) m[e.path().filename().string()] = slurp(e.path());
  return m;
}

}  // namespace

TEST_CASE("simulate bright: SIGTERM writes a checkpoint and complete outputs, exit 143 — the restart equals the uninterrupted run") {
  const fs::path dir = fs::temp_directory_path() / ("lrchain-interrupt-test-" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  const fs::path out = dir / "interrupted", full = dir / "full";

  const auto r = interrupt_run(out, SIGTERM);
  REQUIRE(r.exited);
  CHECK(r.exit_code == 143);
  // one line on stderr with the exact command that continues the run
  CHECK(std::count(r.error_output.begin(), r.error_output.end(), '\n') == 1);
  CHECK(r.error_output.find("SIGTERM") != std::string::npos);
  CHECK(r.error_output.find("--restart " + (out / "checkpoint.bin").string()) != std::string::npos);
  const auto summary = nlohmann::json::parse(r.output);
  CHECK(summary["interrupted"].get<bool>());
  CHECK(summary["t_end"].get<double>() < 300 * summary["ansatz"]["T_b"].get<double>());
  check_files_complete(out);

  // The restart (same command + --restart) completes; so does an uninterrupted run.
  auto restart = bright_args(out);
  restart.insert(restart.end(), {"--restart", (out / "checkpoint.bin").string()});
  lrchain::ProcessOptions quiet;
  quiet.capture_stdout = quiet.capture_stderr = true;
  const auto rr = lrchain::run_program(restart, quiet);
  CHECK(rr.exit_code == 0);
  CHECK(rr.error_output.empty());
  const auto rf = lrchain::run_program(bright_args(full), quiet);
  REQUIRE(rf.exit_code == 0);
  for (const char* f : {"series.csv", "energy_density_spacetime.bin", "snapshot_t0.csv",
                        "snapshot_t433.csv", "snapshot_t867.csv"}) {
    CAPTURE(f);
    REQUIRE(fs::exists(out / f));
    CHECK(slurp(out / f) == slurp(full / f));
  }
  auto a = nlohmann::json::parse(slurp(out / "summary.json"));
  auto b = nlohmann::json::parse(slurp(full / "summary.json"));
  CHECK(a["t_start"].get<double>() > 0);
  // Not part of the trajectory: timings, where the files went, the command line and date of each
  // process, and the work count (the restart evaluates the accelerations once more at its start).
  for (const char* k : {"wall_seconds", "solve_seconds", "out", "checkpoint_file", "checkpoints_written", "t_start",
                        "provenance", "rhs_evaluations"}) {
    a.erase(k);
    b.erase(k);
  }
  for (auto* j : {&a, &b})
    if ((*j)["step_choice"].is_object()) (*j)["step_choice"].erase("probe_seconds");
  CHECK(a == b);

  // changed physics: exit 2, one line naming the item, nothing written
  const auto before = listing(out);
  auto changed = restart;
  changed.insert(changed.end(), {"--rho", "0.5"});
  const auto rc = lrchain::run_program(changed, quiet);
  CHECK(rc.exit_code == 2);
  CHECK(rc.error_output.find("this run has rho = 0.5") != std::string::npos);
  CHECK(std::count(rc.error_output.begin(), rc.error_output.end(), '\n') == 1);
  CHECK(listing(out) == before);
  // a truncated checkpoint: exit 2 naming it
  const std::string bytes = slurp(out / "checkpoint.bin");
  {
    std::ofstream t(dir / "truncated.bin", std::ios::binary);
    t.write(bytes.data(), std::streamsize(bytes.size() / 2));
  }
  auto damaged = bright_args(out);
  damaged.insert(damaged.end(), {"--restart", (dir / "truncated.bin").string()});
  const auto rd = lrchain::run_program(damaged, quiet);
  CHECK(rd.exit_code == 2);
  CHECK(rd.error_output.find((dir / "truncated.bin").string()) != std::string::npos);
  CHECK(listing(out) == before);
  fs::remove_all(dir);
}

TEST_CASE("simulate bright: SIGINT stops the run with exit 130 and a checkpoint") {
  const fs::path dir = fs::temp_directory_path() / ("lrchain-interrupt-int-" + std::to_string(::getpid()));
  fs::remove_all(dir);
  const auto r = interrupt_run(dir / "out", SIGINT);
  REQUIRE(r.exited);
  CHECK(r.exit_code == 130);
  CHECK(r.error_output.find("SIGINT") != std::string::npos);
  check_files_complete(dir / "out");
  fs::remove_all(dir);
}

TEST_CASE("dark continue: SIGTERM stops after the current branch point, writes the branch so far, exit 143") {
  const fs::path dir = fs::temp_directory_path() / ("lrchain-interrupt-dark-" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  lrchain::ProcessOptions o;
  o.capture_stdout = true;
  o.stderr_file = dir / "stderr.txt";  // the per-point progress lines, polled below
  lrchain::ChildProcess child({LRCHAIN_CLI, "dark", "continue", "--omega-b", "2.445", "--rho", "1/3",
                               "--center", "bond", "--sites", "31", "--points", "1000", "--out",
                               (dir / "out").string()},
                              o);
  const auto give_up = std::chrono::steady_clock::now() + std::chrono::seconds(120);
  while (slurp(dir / "stderr.txt").find("point   2 ") == std::string::npos &&
         std::chrono::steady_clock::now() < give_up)
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  child.send_signal(SIGTERM);
  const auto r = child.wait();
  REQUIRE(r.exited);
  CHECK(r.exit_code == 143);
  const std::string err = slurp(dir / "stderr.txt");
  CHECK(err.find("interrupted by SIGTERM after") != std::string::npos);
  const auto j = nlohmann::json::parse(r.output);
  CHECK(j["interrupted"].get<bool>());
  const std::size_t points = j["points"].get<std::size_t>();
  CHECK(points >= 3);
  CHECK(points < 1000);
  // branch.csv: a header and one complete row per point
  const std::string csv = slurp(dir / "out" / "branch.csv");
  CHECK(std::size_t(std::count(csv.begin(), csv.end(), '\n')) == points + 1);
  for (const auto& e : fs::directory_iterator(dir / "out")) CHECK(e.path().filename().string()[0] != '.');
  fs::remove_all(dir);
}

namespace {

// True once process `pid` catches `signal_number` (its SigCgt mask in /proc/PID/status), i.e. its
// handlers are installed and the run is under way; false if it ended first or after `seconds`.
bool catches_signal(int pid, int signal_number, int seconds) {
  const auto give_up = std::chrono::steady_clock::now() + std::chrono::seconds(seconds);
  while (std::chrono::steady_clock::now() < give_up) {
    std::ifstream status("/proc/" + std::to_string(pid) + "/status");
    if (!status) return false;
    for (std::string line; std::getline(status, line);)
      if (line.rfind("SigCgt:", 0) == 0 && (std::stoull(line.substr(7), nullptr, 16) >> (signal_number - 1) & 1ULL) != 0)
        return true;
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  return false;
}

}  // namespace

TEST_CASE("SIGTERM/SIGINT during model-file runs: exit 143/130, one line naming the signal, nothing written") {
  // Runs far longer than the test waits: the signal must end them at their next step or sample.
  const std::vector<std::pair<std::vector<std::string>, int>> runs = {
      {{"simulate", "bright", "--model", "models/fput.toml", "--branch", "acoustic", "--theta", "pi/2", "--sites",
        "20001", "--periods", "20000"}, SIGTERM},
      {{"simulate", "ring", "--model", "models/klein_gordon.toml", "--branch", "branch0", "--theta", "pi/2",
        "--periods", "100000"}, SIGINT}};
  for (const auto& [args, signal_number] : runs) {
    const fs::path out = fs::temp_directory_path() / ("lrchain_model_interrupt_" + std::to_string(::getpid()));
    fs::remove_all(out);
    std::vector<std::string> argv = {LRCHAIN_CLI};
    argv.insert(argv.end(), args.begin(), args.end());
    argv.insert(argv.end(), {"--out", out.string()});
    CAPTURE(args[1]);
    lrchain::ProcessOptions o;
    o.capture_stdout = o.capture_stderr = true;
    o.working_directory = LRCHAIN_SOURCE_DIR;
    lrchain::ChildProcess child(argv, o);
    REQUIRE(catches_signal(child.pid(), signal_number, 120));
    child.send_signal(signal_number);
    const lrchain::ProcessResult r = child.wait();
    CHECK(r.exited);
    CHECK(r.exit_code == 128 + signal_number);
    CHECK(r.output.empty());
    CHECK(std::count(r.error_output.begin(), r.error_output.end(), '\n') == 1);
    CHECK(r.error_output.find(signal_number == SIGTERM ? "SIGTERM" : "SIGINT") != std::string::npos);
    CHECK_FALSE(fs::exists(out));
  }
}
