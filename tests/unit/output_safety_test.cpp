// Output directories are data, never code, and never lose what the user put there: figures drawn
// into a directory named with shell syntax, gnuplot missing, reproduce --out refusing directories
// it did not write, one run per --out (advisory lock), reproduce stopping its child runs on SIGTERM.
#include <doctest/doctest.h>

#include <signal.h>
#include <unistd.h>

#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <string>
#include <thread>
#include <vector>

#include "../support/run_lrchain.hpp"

using namespace lrchain::test;
namespace fs = std::filesystem;

namespace {

// A fresh scratch directory for one test case.
fs::path scratch(const std::string& name) {
  const fs::path dir = fs::temp_directory_path() / ("lrchain-safety-" + name + "-" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

std::string read_file(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

void write(const fs::path& file, const std::string& text) {
  fs::create_directories(file.parent_path());
  std::ofstream(file, std::ios::binary) << text;
}

// Every regular file under dir with its bytes.
std::map<std::string, std::string> contents(const fs::path& dir) {
  std::map<std::string, std::string> files;
  for (const auto& e : fs::recursive_directory_iterator(dir))
    if (e.is_regular_file()) files[e.path().lexically_relative(dir).string()] = read_file(e.path());
  return files;
}

bool is_png(const fs::path& file) { return read_file(file).rfind("\x89PNG\r\n\x1a\n", 0) == 0; }

// Names in dir starting with '.' (temporary files, logs, locks).
std::vector<std::string> hidden_files(const fs::path& dir) {
  std::vector<std::string> hidden;
  for (const auto& e : fs::directory_iterator(dir))
    if (e.path().filename().string()[0] == '.') hidden.push_back(e.path().filename().string());
  return hidden;
}

int count_lines(const std::string& text) {
  int n = 0;
  for (char c : text) n += c == '\n';
  return n;
}

// The text of /proc/PID/FILE, or "" when that process has already ended (listed, then gone).
std::string read_proc(const fs::path& file) {
  try {
    return read_file(file);
  } catch (const std::exception&) {
    return {};
  }
}

// Pids of running processes whose parent is `parent`, or whose command line contains `text`.
std::vector<int> processes(int parent, const std::string& text) {
  std::vector<int> found;
  for (const auto& e : fs::directory_iterator("/proc")) {
    const std::string name = e.path().filename().string();
    if (name.find_first_not_of("0123456789") != std::string::npos) continue;
    const std::string stat = read_proc(e.path() / "stat");
    const auto close = stat.rfind(')');
    if (close == std::string::npos) continue;
    char state = 0;
    int ppid = 0;
    if (std::sscanf(stat.c_str() + close + 1, " %c %d", &state, &ppid) != 2 || state == 'Z') continue;
    std::string cmdline = read_proc(e.path() / "cmdline");
    if ((parent > 0 && ppid == parent) || (!text.empty() && cmdline.find(text) != std::string::npos))
      found.push_back(std::stoi(name));
  }
  return found;
}

// Waits up to `seconds` for `ready`.
template <class F>
bool wait_for(F ready, double seconds) {
  const auto end = std::chrono::steady_clock::now() + std::chrono::duration<double>(seconds);
  while (std::chrono::steady_clock::now() < end) {
    if (ready()) return true;
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  return ready();
}

const std::vector<std::string> small_bright = {"simulate", "bright", "--branch", "optical", "--theta", "pi/2",
                                               "--sites",  "121",     "--periods", "4", "--snapshots", "0", "2", "4"};

std::vector<std::string> with_out(std::vector<std::string> args, const std::string& out) {
  args.push_back("--out");
  args.push_back(out);
  return args;
}

}  // namespace

TEST_CASE("figures are drawn into a directory whose name is shell syntax, and nothing runs") {
  REQUIRE_MESSAGE(lrchain::program_in_path("gnuplot"), "gnuplot (Debian gnuplot-nox) is needed by this test");
  const fs::path base = scratch("shell-name");
  const std::string name = "out $(touch X); 'q' \"d\" ünïcödé";
  const fs::path out = base / name;
  struct Job {
    std::vector<std::string> args;
    std::vector<std::string> pngs;
  };
  const std::vector<Job> jobs = {
      {with_out(small_bright, name), {"snapshots.png", "energy.png"}},  // the name itself as --out
      {{"regime", "map", "--nx", "20", "--ny", "20", "--no-curves", "--out", name + "/map"}, {"regime_theta-rho.png"}},
      {{"dark", "solve", "--omega-b", "2.42", "--sites", "41", "--quiet", "--out", name + "/dark"}, {"profile.png"}},
  };
  for (const auto& job : jobs) {
    const auto run = run_lrchain(job.args, base);  // relative --out, run inside base
    INFO(job.args[0], " ", job.args[1], ": ", run.err);
    REQUIRE(run.exit_code == 0);
    const fs::path dir = base / job.args.back();
    const auto json = nlohmann::json::parse(run.out);
    for (const auto& png : job.pngs) {
      CHECK(is_png(dir / png));
      if (json.contains("figures")) CHECK(std::find(json["figures"].begin(), json["figures"].end(), png) != json["figures"].end());
    }
    CHECK(hidden_files(dir).empty());  // no .gp.log, no temporary image, no lock left
    CHECK(run.err.find("warning") == std::string::npos);
  }
  // `$(touch X)` was never run: no X next to the directory, inside it, or where the test runs.
  CHECK_FALSE(fs::exists(base / "X"));
  CHECK_FALSE(fs::exists(out / "X"));
  CHECK_FALSE(fs::exists(fs::current_path() / "X"));
  fs::remove_all(base);
}

TEST_CASE("without gnuplot: exit 0, data written, one warning naming the figures and gnuplot-nox") {
  const fs::path base = scratch("no-gnuplot");
  const std::vector<std::string> no_gnuplot = {"PATH=/nonexistent"};
  SUBCASE("simulate bright: summary.json lists the figures as skipped") {
    const auto run = run_lrchain(with_out(small_bright, (base / "bright").string()), {}, no_gnuplot);
    REQUIRE(run.exit_code == 0);
    CHECK(count_lines(run.err) == 1);
    CHECK(run.err.find("gnuplot-nox") != std::string::npos);
    CHECK(run.err.find("snapshots.png") != std::string::npos);
    CHECK(run.err.find("energy.png") != std::string::npos);
    const auto summary = nlohmann::json::parse(read_file(base / "bright/summary.json"));
    CHECK(summary["figures"].empty());
    CHECK(summary["figures_skipped"] == nlohmann::json({"snapshots.png", "energy.png"}));
    for (const char* f : {"series.csv", "snapshot_t0.csv", "energy_density_spacetime.bin", "snapshots.gp", "energy.gp"})
      CHECK(fs::exists(base / "bright" / f));
    CHECK_FALSE(fs::exists(base / "bright/snapshots.png"));
    CHECK(hidden_files(base / "bright").empty());
  }
  SUBCASE("dark solve and regime map: the JSON lists the figures as skipped") {
    const auto dark = run_lrchain({"dark", "solve", "--omega-b", "2.42", "--sites", "41", "--quiet", "--out",
                                   (base / "dark").string()}, {}, no_gnuplot);
    REQUIRE(dark.exit_code == 0);
    CHECK(count_lines(dark.err) == 1);
    CHECK(dark.err.find("profile.png") != std::string::npos);
    CHECK(dark.err.find("gnuplot-nox") != std::string::npos);
    const auto dj = nlohmann::json::parse(dark.out);
    CHECK(dj["figures_skipped"] == nlohmann::json({"profile.png"}));
    CHECK(fs::exists(base / "dark/profile.csv"));
    CHECK(hidden_files(base / "dark").empty());
    const auto map = run_lrchain({"regime", "map", "--nx", "20", "--ny", "20", "--no-curves", "--out",
                                  (base / "map").string()}, {}, no_gnuplot);
    REQUIRE(map.exit_code == 0);
    CHECK(count_lines(map.err) == 1);
    CHECK(map.err.find("regime_theta-rho.png") != std::string::npos);
    const auto mj = nlohmann::json::parse(map.out);
    CHECK(mj["figures_skipped"] == nlohmann::json({"regime_theta-rho.png"}));
    CHECK(fs::exists(base / "map/regime_theta-rho_optical.csv"));
    CHECK(hidden_files(base / "map").empty());
  }
  fs::remove_all(base);
}

TEST_CASE("gnuplot failing: exit 0, one warning naming the figure and why, no temporary file left") {
  const fs::path base = scratch("gnuplot-fails");
  // A "gnuplot" that draws nothing and exits 1 (a copy of false(1)), first in PATH.
  fs::create_directories(base / "bin");
  fs::copy_file("/bin/false", base / "bin/gnuplot");
  const char* path = std::getenv("PATH");
  const auto run = run_lrchain(with_out(small_bright, (base / "bright").string()), {},
                               {"PATH=" + (base / "bin").string() + ":" + (path ? path : "/usr/bin:/bin")});
  REQUIRE(run.exit_code == 0);
  CHECK(count_lines(run.err) == 1);
  CHECK(run.err.find("snapshots.png (gnuplot failed on snapshots.gp)") != std::string::npos);
  CHECK(run.err.find("energy.png (gnuplot failed on energy.gp)") != std::string::npos);
  const auto summary = nlohmann::json::parse(read_file(base / "bright/summary.json"));
  CHECK(summary["figures"].empty());
  CHECK(summary["figures_skipped"].size() == 2);
  CHECK(hidden_files(base / "bright").empty());
  fs::remove_all(base);
}

TEST_CASE("reproduce --out never deletes what lrchain did not write") {
  const fs::path base = scratch("reproduce-out");
  const fs::path user = base / "mine";
  write(user / "index.html", "<p>my own page</p>\n");
  write(user / "notes.txt", "do not lose me\n");
  write(user / "sub/data.csv", "x,y\n1,2\n");
  const auto before = contents(base);
  const std::vector<std::string> quick = {"reproduce", "--quick", "--only", "coefficients", "--out"};
  auto refused = [&](const std::string& out, const fs::path& cwd, const std::string& named) {
    auto args = quick;
    args.push_back(out);
    const auto run = run_lrchain(args, cwd);
    INFO("--out ", out, " in ", cwd.string(), ": ", run.err);
    CHECK(run.exit_code == 2);
    CHECK(count_lines(run.err) == 1);
    CHECK(run.err.find(named) != std::string::npos);
    CHECK(contents(base) == before);  // every user file, byte for byte, and nothing new
  };
  // A directory holding an index.html that lrchain did not write, by any spelling.
  refused(user.string(), base, user.string());
  refused("mine", base, "mine");
  refused(".", user, "'.");  // the current directory
  refused("./", user, "'./");
  refused(user.string() + "/", user, user.string());
  refused("..", user / "sub", "'..");  // a parent of the current directory
  refused(base.string(), user, base.string());
  // A DIR.partial that lrchain did not create.
  write(base / "report.partial/draft.txt", "user draft\n");
  const auto with_partial = contents(base);
  {
    auto args = quick;
    args.push_back((base / "report").string());
    const auto run = run_lrchain(args, base);
    CHECK(run.exit_code == 2);
    CHECK(run.err.find((base / "report.partial").string()) != std::string::npos);
    CHECK(contents(base) == with_partial);
    CHECK_FALSE(fs::exists(base / "report"));
  }
  // A report lrchain wrote carries its marker and is replaced by the next run; no lock is left.
  auto args = quick;
  args.push_back((base / "done").string());
  REQUIRE(run_lrchain(args, base).exit_code == 0);
  CHECK(read_file(base / "done/.lrchain-report").rfind("lrchain report\n", 0) == 0);
  write(base / "done/coefficients/stale.txt", "from an earlier run\n");
  REQUIRE(run_lrchain(args, base).exit_code == 0);
  CHECK_FALSE(fs::exists(base / "done/coefficients/stale.txt"));
  CHECK(fs::exists(base / "done/index.html"));
  CHECK_FALSE(fs::exists(base / "done/.lrchain-lock"));
  CHECK_FALSE(fs::exists(base / "done.partial"));
  CHECK(read_file(user / "notes.txt") == "do not lose me\n");
  fs::remove_all(base);
}

TEST_CASE("two runs into one --out: the second exits 2 naming the running one") {
  const fs::path base = scratch("lock");
  const fs::path out = base / "shared";
  auto long_run = with_out(small_bright, out.string());
  long_run[9] = "20000";  // --periods: far longer than the test waits
  lrchain::ProcessOptions quiet;
  quiet.stdout_file = base / "first.json";
  quiet.stderr_file = base / "first.log";
  std::vector<std::string> argv{LRCHAIN_CLI};
  argv.insert(argv.end(), long_run.begin(), long_run.end());
  lrchain::ChildProcess first(argv, quiet);
  REQUIRE(wait_for([&] { return fs::exists(out / ".lrchain-lock"); }, 30));
  const auto second = run_lrchain(with_out(small_bright, out.string()));
  CHECK(second.exit_code == 2);
  CHECK(count_lines(second.err) == 1);
  CHECK(second.err.find("pid " + std::to_string(first.pid())) != std::string::npos);
  CHECK(second.err.find(out.string()) != std::string::npos);
  CHECK_FALSE(fs::exists(out / "summary.json"));  // the second wrote nothing
  first.send_signal(SIGTERM);
  const auto r = first.wait();
  CHECK((r.exit_code == 143 || r.signal_number == SIGTERM));
  // Once the first has ended the directory is free again (once its checkpoint is moved away: a
  // new run refuses an earlier run's checkpoint, cli_input_limits_test.cpp).
  fs::remove(out / "checkpoint.bin");
  CHECK(run_lrchain(with_out(small_bright, out.string())).exit_code == 0);
  CHECK_FALSE(fs::exists(out / ".lrchain-lock"));
  fs::remove_all(base);
}

TEST_CASE("reproduce holds its --out — on SIGTERM it stops its child runs, leaves nothing and exits 143") {
  const fs::path base = scratch("reproduce-sigterm");
  const fs::path out = base / "report-sigterm-unique";
  lrchain::ProcessOptions quiet;
  quiet.stdout_file = base / "reproduce.json";
  quiet.stderr_file = base / "reproduce.log";
  lrchain::ChildProcess reproduce({LRCHAIN_CLI, "reproduce", "--quick", "--only", "dark_optical_bond", "--out",
                                   out.string()}, quiet);
  // dark_optical_bond runs `lrchain dark continue` for about 30 s: wait until it has started.
  REQUIRE(wait_for([&] { return !processes(reproduce.pid(), "").empty(); }, 30));
  // A second reproduce into the same --out is refused while the first runs, and touches nothing.
  const auto files_before = contents(out.string() + ".partial");
  const auto second = run_lrchain({"reproduce", "--quick", "--only", "coefficients", "--out", out.string()});
  CHECK(second.exit_code == 2);
  CHECK(second.err.find("pid " + std::to_string(reproduce.pid())) != std::string::npos);
  CHECK(contents(out.string() + ".partial").size() >= files_before.size());
  CHECK(fs::exists(fs::path(out.string() + ".partial") / ".lrchain-report"));
  reproduce.send_signal(SIGTERM);
  const auto r = reproduce.wait();
  INFO(read_file(base / "reproduce.log"));
  CHECK(r.exit_code == 143);
  CHECK(processes(0, out.string()).empty());  // no lrchain run started for this report is left
  CHECK_FALSE(fs::exists(out));
  CHECK_FALSE(fs::exists(out.string() + ".partial"));
  CHECK(contents(base).size() == 2);  // only this test's reproduce.json and reproduce.log
  fs::remove_all(base);
}
