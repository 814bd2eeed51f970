// `lrchain sweep`: a sweep's results do not depend on the thread count or on MPI ranks (bit for
// bit: each point's run depends on its parameters only); a sweep stopped by SIGINT and resumed gives
// the uninterrupted sweep's results; a failing point is recorded and the sweep finishes; bad sweep
// files exit 2 naming the key and write nothing. The expected values are the same sweep run
// another way (1 thread, uninterrupted), plus the single run of `lrchain simulate` for one point.
#include <doctest/doctest.h>

#include <signal.h>
#include <unistd.h>

#include <algorithm>
#include <cctype>

#include <chrono>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>
#include <thread>
#include <vector>

#include <nlohmann/json.hpp>

#include "lrchain/process.hpp"
#include "lrchain/sim/resonant_chain_bright_run.hpp"
#include "lrchain/jobs/experiment_config.hpp"
#include "lrchain/jobs/sweep/results_file.hpp"
#include "lrchain/jobs/sweep/sweep_config.hpp"
#include "lrchain/jobs/sweep/sweep_run.hpp"
#include "../support/run_lrchain.hpp"
#include "sweep_test_files.hpp"

namespace fs = std::filesystem;
using namespace lrchain::jobs::sweep;

namespace {

fs::path scratch(const std::string& name) { return lrchain::test::sweep_scratch("sweep-test", name); }
void write(const fs::path& f, const std::string& text) { lrchain::test::write_text(f, text); }
const char* const base_config = lrchain::test::short_bright_base;

// theta across part of the focusing interval x detuning over a decade: 4 x 3 points.
std::string grid_sweep(const std::string& output, double checkpoint_seconds = 30) {
  return "job = \"bright\"\nbase = \"base.toml\"\noutput = \"" + output + "\"\ncheckpoint_seconds = " +
         std::to_string(checkpoint_seconds) +
         "\n[[axis]]\nparameter = \"bright.theta\"\nfrom = 1.2\nto = 1.8\ncount = 4\n"
         "[[axis]]\nparameter = \"bright.detuning\"\nfrom = -1e-4\nto = -1e-3\ncount = 3\nspacing = \"log\"\n";
}

SweepResults run_in_process(const fs::path& sweep_file, int threads) {
  const SweepConfig c = load_sweep_config(sweep_file);
  const Job job = make_job(c);
  SweepRunOptions o;
  o.threads = threads;
  o.progress = false;
  run_sweep(c, job, o);
  return read_results(c.output, c, job.scalar_names());
}

// Same scalars (bit for bit, NaN included), statuses and reasons.
void check_same(const SweepResults& a, const SweepResults& b) {
  REQUIRE(a.points == b.points);
  REQUIRE(a.scalars.size() == b.scalars.size());
  CHECK(std::memcmp(a.scalars.data(), b.scalars.data(), a.scalars.size() * sizeof(double)) == 0);
  CHECK(a.status == b.status);
  CHECK(a.reasons == b.reasons);
}

}  // namespace

TEST_CASE("sweep: 1 thread and 2 threads give the same results bit for bit — a point equals its single run") {
  const fs::path d = scratch("threads");
  write(d / "base.toml", base_config);
  write(d / "one.toml", grid_sweep((d / "one.h5").string()));
  write(d / "two.toml", grid_sweep((d / "two.h5").string()));
  const SweepResults one = run_in_process(d / "one.toml", 1);
  const SweepResults two = run_in_process(d / "two.toml", 2);
  CHECK(one.finished() == 12);
  CHECK(one.failed() == 0);
  check_same(one, two);
  // Point (theta = 1.8, detuning = -1e-3) is the last one; the same run through the simulate config.
  lrchain::jobs::ExperimentConfig ec = lrchain::jobs::load_experiment_config(d / "base.toml");
  ec.bright.theta = 1.8;
  ec.bright.detuning = -1e-3;
  const auto single = lrchain::sim::run_resonant_chain_bright(ec.bright).summary;
  const std::size_t last = 11;
  CHECK(one.scalars[0 * one.points + last] == single.max_Ex);  // scalar 0 is max_Ex
  CHECK(one.scalars[7 * one.points + last] == single.centre_speed);
  CHECK(single.max_Ex > 0);
  CHECK(fs::exists(d / "one.csv"));
  fs::remove_all(d);
}

TEST_CASE("sweep: a failing point is recorded with its reason and the sweep finishes") {
  const fs::path d = scratch("failing");
  write(d / "base.toml", base_config);
  // theta = 2.5 lies outside the optical focusing interval (0, 1.8916) at rho = 1/3 (docs/regime-maps.md):
  // the ansatz refuses it.
  write(d / "s.toml", "job = \"bright\"\nbase = \"base.toml\"\noutput = \"" + (d / "s.h5").string() +
                          "\"\nlayout = \"list\"\n[[axis]]\nparameter = \"bright.theta\"\nvalues = [1.5, 2.5, 1.7]\n");
  const auto r = lrchain::test::run_lrchain({"sweep", "--config", (d / "s.toml").string(), "--json"});
  REQUIRE_MESSAGE(r.exit_code == 0, r.err);
  // stderr is not a terminal here: plain progress lines, the last one with every point done.
  CHECK(r.err.find("sweep: 3/3 points (100.0%)") != std::string::npos);
  CHECK(r.err.find('\r') == std::string::npos);
  const auto j = nlohmann::json::parse(r.out);
  CHECK(j["finished"] == 3);
  CHECK(j["failed"] == 1);
  const SweepConfig c = load_sweep_config(d / "s.toml");
  const SweepResults res = read_results(c.output, c, make_job(c).scalar_names());
  CHECK(res.status[0] == std::int8_t(PointStatus::ok));
  CHECK(res.status[1] == std::int8_t(PointStatus::invalid));
  CHECK(res.status[2] == std::int8_t(PointStatus::ok));
  CHECK(!res.reasons[1].empty());
  CHECK(std::isnan(res.scalars[1]));
  fs::remove_all(d);
}

TEST_CASE("sweep: stopped by SIGINT and run again, it gives the uninterrupted results — a changed config refuses to resume") {
  const fs::path d = scratch("resume");
  // Longer runs (401 sites, 100 T_b: tens of ms each) so that the signal comes mid-way.
  std::string longer = base_config;
  longer.replace(longer.find("sites = 121"), 11, "sites = 401");
  longer.replace(longer.find("periods = 10"), 12, "periods = 100");
  write(d / "base.toml", longer);
  // 8 x 5 points, one thread, the file rewritten every 0.05 s.
  auto sweep = [&](const std::string& out) {
    return "job = \"bright\"\nbase = \"base.toml\"\noutput = \"" + (d / out).string() +
           "\"\ncheckpoint_seconds = 0.05\n[[axis]]\nparameter = \"bright.theta\"\nfrom = 1.2\nto = 1.8\ncount = 8\n"
           "[[axis]]\nparameter = \"bright.n0\"\nvalues = [0, 0.25, 0.5, 0.75, 1]\n";
  };
  write(d / "whole.toml", sweep("whole.h5"));
  write(d / "parts.toml", sweep("parts.h5"));
  const SweepResults whole = run_in_process(d / "whole.toml", 1);
  {
    lrchain::ProcessOptions o;
    o.capture_stdout = o.capture_stderr = true;
    lrchain::ChildProcess child({LRCHAIN_CLI, "sweep", "--config", (d / "parts.toml").string(), "--threads", "1"}, o);
    const auto give_up = std::chrono::steady_clock::now() + std::chrono::seconds(60);
    while (!fs::exists(d / "parts.h5") && std::chrono::steady_clock::now() < give_up)
      std::this_thread::sleep_for(std::chrono::milliseconds(2));
    child.send_signal(SIGINT);
    const auto r = child.wait();
    CHECK(r.exit_code == 130);
    CHECK(r.error_output.find("run the same command again") != std::string::npos);
  }
  const SweepConfig c = load_sweep_config(d / "parts.toml");
  const SweepResults part = read_results(c.output, c, make_job(c).scalar_names());
  CHECK(part.finished() > 0);
  CHECK(part.finished() < part.points);  // stopped mid-way
  const auto again = lrchain::test::run_lrchain({"sweep", "--config", (d / "parts.toml").string(), "--json", "--quiet"});
  REQUIRE_MESSAGE(again.exit_code == 0, again.err);
  const auto j = nlohmann::json::parse(again.out);
  CHECK(j["resumed"] == part.finished());
  CHECK(j["ran"] == 40 - part.finished());
  check_same(whole, read_results(c.output, c, make_job(c).scalar_names()));
  // The same results file with another base config: exit 2 naming what changed, file untouched.
  const auto before = fs::last_write_time(d / "parts.h5");
  write(d / "base.toml", longer + "abs_tol = 1e-10\n");
  const auto changed = lrchain::test::run_lrchain({"sweep", "--config", (d / "parts.toml").string(), "--quiet"});
  CHECK(changed.exit_code == 2);
  CHECK(changed.err.find("base config changed") != std::string::npos);
  CHECK(fs::last_write_time(d / "parts.h5") == before);
  fs::remove_all(d);
}

TEST_CASE("sweep: bad sweep files exit 2 naming the key, and write nothing") {
  const fs::path d = scratch("bad");
  write(d / "base.toml", base_config);
  const std::string head = "base = \"base.toml\"\noutput = \"" + (d / "out" / "r.h5").string() + "\"\n";
  const std::string axis = "[[axis]]\nparameter = \"bright.theta\"\nvalues = [1.5]\n";
  struct Case {
    std::string text, expected;
  };
  const Case cases[] = {
      {"job = \"brigth\"\n" + head + axis, "'job'"},                                            // unknown job
      {"job = \"bright\"\n" + head + "[[axis]]\nparameter = \"bright.thta\"\nvalues = [1]\n", "did you mean 'bright.theta'"},
      // a renamed key: named with its new name and, for bright.N, its new meaning
      {"job = \"bright\"\n" + head + "[[axis]]\nparameter = \"bright.N\"\nvalues = [50]\n",
       "'bright.N' was renamed: use 'bright.sites', the number of strain sites 2N + 1"},
      {"job = \"bright\"\n" + head + "[[axis]]\nparameter = \"bright.theta\"\nvalues = []\n", "'values'"},  // empty list
      {"job = \"bright\"\n" + head + "[[axis]]\nparameter = \"bright.theta\"\nfrom = 1\nto = 2\ncount = 0\n", "'count'"},
      {"job = \"bright\"\n" + head + "[[axis]]\nparameter = \"bright.theta\"\nfrom = 1\nto = 1\ncount = 3\n", "empty"},
      {"job = \"bright\"\nouptut = 1\n" + head + axis, "did you mean 'output'"},              // unknown key
      {"job = \"drive\"\n" + head + axis, "not \"drive\""},                                     // base of another job
      {"job = \"bright\"\n" + head, "[axis]"},                                                  // no axis
  };
  for (const auto& k : cases) {
    CAPTURE(k.text);
    write(d / "s.toml", k.text);
    const auto r = lrchain::test::run_lrchain({"sweep", "--config", (d / "s.toml").string()});
    CHECK(r.exit_code == 2);
    CHECK(r.err.find(k.expected) != std::string::npos);
    CHECK(r.err.find("s.toml") != std::string::npos);
    CHECK(std::count(r.err.begin(), r.err.end(), '\n') == 1);
    CHECK(!fs::exists(d / "out"));
  }
  fs::remove_all(d);
}

#ifdef LRCHAIN_TEST_MPI
TEST_CASE("sweep: mpirun -n 2 gives the 1-rank threaded results bit for bit") {
  REQUIRE_MESSAGE(lrchain::program_in_path("mpirun"), "this build has MPI: mpirun (openmpi-bin) must be installed");
  const fs::path d = scratch("mpi");
  write(d / "base.toml", base_config);
  write(d / "threads.toml", grid_sweep((d / "threads.h5").string()));
  write(d / "ranks.toml", grid_sweep((d / "ranks.h5").string()));
  const SweepResults threads = run_in_process(d / "threads.toml", 2);
  // CI runs as root: Open MPI refuses that unless told.
  const auto r = lrchain::test::run_command({"mpirun", "-n", "2", "--oversubscribe", "--allow-run-as-root", LRCHAIN_CLI,
                                             "sweep", "--config", (d / "ranks.toml").string(), "--json", "--quiet",
                                             "--threads", "1"});
  REQUIRE_MESSAGE(r.exit_code == 0, r.err);
  const auto j = nlohmann::json::parse(r.out);
  CHECK(j["ranks"] == 2);
  CHECK(j["finished"] == 12);
  const SweepConfig c = load_sweep_config(d / "ranks.toml");
  check_same(threads, read_results(c.output, c, make_job(c).scalar_names()));
  fs::remove_all(d);
}

namespace {

// The pid of the process whose command line contains `needle` and whose environment says it is
// MPI rank `rank` (Open MPI's OMPI_COMM_WORLD_RANK); 0 if there is none (yet).
int pid_of_rank(const std::string& needle, int rank) {
  const std::string wanted = "OMPI_COMM_WORLD_RANK=" + std::to_string(rank);
  for (const auto& e : fs::directory_iterator("/proc")) {
    const std::string name = e.path().filename().string();
    if (name.empty() || !std::all_of(name.begin(), name.end(), ::isdigit)) continue;
    std::ifstream cmd(e.path() / "cmdline", std::ios::binary), env(e.path() / "environ", std::ios::binary);
    const std::string cmdline{std::istreambuf_iterator<char>(cmd), std::istreambuf_iterator<char>()};
    if (cmdline.find(needle) == std::string::npos || cmdline.rfind("mpirun", 0) == 0) continue;
    for (std::string entry; std::getline(env, entry, '\0');)
      if (entry == wanted) return std::stoi(name);
  }
  return 0;
}

}  // namespace

TEST_CASE("sweep: under mpirun -n 2, a refused output ends every rank with exit 2 and replaces nothing") {
  REQUIRE_MESSAGE(lrchain::program_in_path("mpirun"), "this build has MPI: mpirun (openmpi-bin) must be installed");
  const fs::path d = scratch("mpi-refused");
  write(d / "base.toml", base_config);
  write(d / "s.toml", grid_sweep((d / "s.h5").string()));
  write(d / "s.csv", "the user's own table\n");  // where the sweep's CSV view would go
  const auto r = lrchain::test::run_command({"mpirun", "-n", "2", "--oversubscribe", "--allow-run-as-root", LRCHAIN_CLI, "sweep",
                                             "--config", (d / "s.toml").string(), "--quiet", "--threads", "1"});
  // Before: the sweep ran and replaced s.csv (exit 0); a refusal on rank 0 alone left rank 1
  // waiting for points forever.
  CHECK(r.exit_code == 2);
  CHECK(r.err.find("s.csv' exists and was not written by this sweep") != std::string::npos);
  std::ifstream in(d / "s.csv");
  CHECK(std::string{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()} == "the user's own table\n");
  CHECK(!fs::exists(d / "s.h5"));
  fs::remove_all(d);
}

TEST_CASE("sweep: under mpirun -n 2, SIGTERM to rank 1 stops the sweep with exit 143, interrupted and the missing points listed") {
  REQUIRE_MESSAGE(lrchain::program_in_path("mpirun"), "this build has MPI: mpirun (openmpi-bin) must be installed");
  const fs::path d = scratch("mpi-term");
  // Points of tens of ms (401 sites, 100 T_b), 8 x 5 of them: the signal comes mid-way.
  std::string longer = base_config;
  longer.replace(longer.find("sites = 121"), 11, "sites = 401");
  longer.replace(longer.find("periods = 10"), 12, "periods = 100");
  write(d / "base.toml", longer);
  write(d / "term.toml", "job = \"bright\"\nbase = \"base.toml\"\noutput = \"" + (d / "term.h5").string() +
                             "\"\ncheckpoint_seconds = 0.05\n[[axis]]\nparameter = \"bright.theta\"\nfrom = 1.2\nto = 1.8\ncount = 8\n"
                             "[[axis]]\nparameter = \"bright.n0\"\nvalues = [0, 0.25, 0.5, 0.75, 1]\n");
  lrchain::ProcessOptions o;
  o.capture_stdout = o.capture_stderr = true;
  lrchain::ChildProcess mpirun({"mpirun", "-n", "2", "--oversubscribe", "--allow-run-as-root", LRCHAIN_CLI, "sweep", "--config",
                                (d / "term.toml").string(), "--json", "--quiet", "--threads", "1"},
                               o);
  // Once rank 0 has written its first checkpoint, both ranks are running points.
  const auto give_up = std::chrono::steady_clock::now() + std::chrono::seconds(60);
  int rank1 = 0;
  while (std::chrono::steady_clock::now() < give_up && (!fs::exists(d / "term.h5") || !rank1)) {
    rank1 = pid_of_rank((d / "term.toml").string(), 1);
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  REQUIRE(rank1 > 0);
  REQUIRE(::kill(rank1, SIGTERM) == 0);
  const auto r = mpirun.wait();
  // Before: exit 0, "interrupted": false and the points rank 1 held silently absent.
  CHECK(r.exit_code == 143);
  const auto j = nlohmann::json::parse(r.output);
  CHECK(j["interrupted"] == true);
  const SweepConfig c = load_sweep_config(d / "term.toml");
  const SweepResults res = read_results(c.output, c, make_job(c).scalar_names());
  CHECK(j["missing"] == res.points - res.finished());
  CHECK(j["missing"].get<std::size_t>() > 0);
  std::vector<std::size_t> missing;
  for (std::size_t p = 0; p < res.points; ++p)
    if (res.status[p] == std::int8_t(PointStatus::missing)) missing.push_back(p);
  CHECK(j["missing_points"].get<std::vector<std::size_t>>() == missing);
  CHECK(r.error_output.find("interrupted by SIGTERM on another rank") != std::string::npos);
  // Run again (as the message says), it completes the sweep.
  const auto again = lrchain::test::run_command({"mpirun", "-n", "2", "--oversubscribe", "--allow-run-as-root", LRCHAIN_CLI,
                                                 "sweep", "--config", (d / "term.toml").string(), "--json", "--quiet", "--threads", "1"});
  REQUIRE_MESSAGE(again.exit_code == 0, again.err);
  CHECK(nlohmann::json::parse(again.out)["finished"] == 40);
  fs::remove_all(d);
}
#endif

TEST_CASE("sweep: docs/sweeps.md lists every key of the sweep schema (generated part up to date)") {
  std::ifstream in(fs::path(LRCHAIN_SOURCE_DIR) / "docs" / "sweeps.md");
  const std::string doc{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  const std::string begin = "<!-- generated from the schema: begin -->\n", end = "<!-- generated from the schema: end -->";
  const auto a = doc.find(begin), b = doc.find(end);
  REQUIRE(a != std::string::npos);
  REQUIRE(b != std::string::npos);
  const std::string generated = sweep_config_markdown();
  const bool same = doc.substr(a + begin.size(), b - a - begin.size()) == generated;
  if (!same) std::ofstream("sweeps-md-expected.txt") << generated;
  CHECK_MESSAGE(same, "docs/sweeps.md is out of date with the sweep schema: the expected text is in "
                      "sweeps-md-expected.txt of the test's working directory");
}

TEST_CASE("sweep: the shipped sweep files load — the optical atlas is 38 theta x 9 detunings") {
  int loaded = 0;
  // From the source directory, as the examples say: a model-file base names its model relative to it.
  const fs::path here = fs::current_path();
  fs::current_path(LRCHAIN_SOURCE_DIR);
  for (const auto& e : fs::directory_iterator(fs::path(LRCHAIN_SOURCE_DIR) / "examples" / "sweeps")) {
    if (e.path().extension() != ".toml") continue;
    CAPTURE(e.path().string());
    CHECK_NOTHROW(load_sweep_config(e.path()));
    ++loaded;
  }
  fs::current_path(here);
  CHECK(loaded >= 1);
  const SweepConfig atlas = load_sweep_config(fs::path(LRCHAIN_SOURCE_DIR) / "examples" / "sweeps" / "atlas_bright_optical.toml");
  CHECK(atlas.shape() == std::vector<std::size_t>{38, 9});
  // theta in steps of 0.05 from 0.15; |detuning| from 1e-4 to 1e-2, a quarter decade apart.
  CHECK(atlas.axes[0].values[1] == doctest::Approx(0.2).epsilon(1e-15));
  CHECK(atlas.axes[1].values.front() == -1e-4);
  CHECK(atlas.axes[1].values[4] == doctest::Approx(-1e-3).epsilon(1e-14));
  CHECK(atlas.axes[1].values.back() == -1e-2);
  CHECK(atlas.figure == "max_Ex");
}
