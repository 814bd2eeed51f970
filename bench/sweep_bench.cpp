// Throughput of `lrchain sweep` in-process: P exp1-size bright runs (examples/exp1_optical_pi2.toml:
// N = 500, 200 T_b, srkn11b, every observer on) as one sweep over the initial centre n0 (P values in
// [0, 1): the same cost per point, distinct runs), on T threads. Prints one JSON line: points,
// threads, seconds, points per second, and the process's peak resident memory (for "memory flat in
// the number of points": compare P = 100 with P = 1000), the CPU time (user + sys) and the load
// average (1 min) before and after: on a shared machine the wall time alone says little.
//   sweep_bench [points=1000] [threads=all] [exp1 config=examples/exp1_optical_pi2.toml]
// Parallel efficiency: t(1 thread) / (2 t(2 threads)). Across MPI ranks, run the sweep file it
// leaves in the temporary directory with `mpirun -n 2 lrchain sweep --config ... --threads 1`.
#include <sys/resource.h>
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <stdlib.h>
#include <filesystem>
#include <fstream>
#include <string>

#include <fmt/format.h>

#include "lrchain/jobs/sweep/sweep_config.hpp"
#include "lrchain/jobs/sweep/sweep_run.hpp"

namespace fs = std::filesystem;
using namespace lrchain::jobs::sweep;

int main(int argc, char** argv) {
  const long points = argc > 1 ? std::atol(argv[1]) : 1000;
  const int threads = argc > 2 ? std::atoi(argv[2]) : 0;
  const fs::path exp1 = fs::absolute(argc > 3 ? argv[3] : "examples/exp1_optical_pi2.toml");
  const fs::path dir = fs::temp_directory_path() / fmt::format("lrchain-sweep-bench-{}", ::getpid());
  fs::create_directories(dir);
  std::string n0 = "[";
  for (long i = 0; i < points; ++i) n0 += fmt::format("{}{}", i ? ", " : "", double(i) / double(points));
  std::ofstream(dir / "bench.toml") << "job = \"bright\"\nbase = \"" << exp1.string() << "\"\noutput = \""
                                    << (dir / "bench.h5").string() << "\"\nlayout = \"list\"\n"
                                    << "[[axis]]\nparameter = \"bright.n0\"\nvalues = " << n0 << "]\n";
  const SweepConfig c = load_sweep_config(dir / "bench.toml");
  const Job job = make_job(c);
  SweepRunOptions o;
  o.threads = threads;
  o.progress = false;
  double load_before[1] = {0}, load_after[1] = {0};
  getloadavg(load_before, 1);
  const auto start = std::chrono::steady_clock::now();
  const SweepOutcome r = run_sweep(c, job, o);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  getloadavg(load_after, 1);
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  const auto cpu = [](const timeval& t) { return double(t.tv_sec) + 1e-6 * double(t.tv_usec); };
  std::printf("{\"points\": %zu, \"finished\": %zu, \"failed\": %zu, \"threads\": %d, \"seconds\": %.3f, "
              "\"cpu_seconds\": %.3f, \"points_per_second\": %.2f, \"max_rss_mib\": %.1f, \"load_before\": %.2f, "
              "\"load_after\": %.2f, \"sweep_file\": \"%s\"}\n",
              r.points, r.finished, r.failed, threads, seconds, cpu(usage.ru_utime) + cpu(usage.ru_stime),
              double(r.ran) / seconds, double(usage.ru_maxrss) / 1024.0, load_before[0], load_after[0],
              (dir / "bench.toml").c_str());
  return r.finished == r.points ? 0 : 1;
}
