#pragma once
// What the sweep tests share: a fresh scratch directory per test, writing a file, running a sweep file in
// process and reading its results, and the short bright base config their sweeps run.
#include <unistd.h>

#include <algorithm>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>

#include <nlohmann/json.hpp>

#include "lrchain/jobs/sweep/results_file.hpp"
#include "lrchain/jobs/sweep/sweep_config.hpp"
#include "lrchain/jobs/sweep/sweep_run.hpp"
#include "../support/run_lrchain.hpp"

namespace lrchain::test {

// A fresh, empty scratch directory <tmp>/lrchain-<prefix>-<name>-<pid>.
inline std::filesystem::path sweep_scratch(const std::string& prefix, const std::string& name) {
  const auto d = std::filesystem::temp_directory_path() / ("lrchain-" + prefix + "-" + name + "-" + std::to_string(::getpid()));
  std::filesystem::remove_all(d);
  std::filesystem::create_directories(d);
  return d;
}

// Writes `text` (bytes as they are) to `file`.
inline void write_text(const std::filesystem::path& file, const std::string& text) {
  std::ofstream(file, std::ios::binary) << text;
}

// Runs the sweep file on `threads` threads, quietly, and reads its results file back.
inline jobs::sweep::SweepResults run_sweep_file(const std::filesystem::path& sweep_file, int threads = 2) {
  const jobs::sweep::SweepConfig c = jobs::sweep::load_sweep_config(sweep_file);
  const jobs::sweep::Job job = jobs::sweep::make_job(c);
  jobs::sweep::SweepRunOptions o;
  o.threads = threads;
  o.progress = false;
  jobs::sweep::run_sweep(c, job, o);
  return jobs::sweep::read_results(c.output, c, job);
}

// The scalar `name` of `point`; std::out_of_range if the job has no such scalar.
inline double sweep_scalar(const jobs::sweep::SweepResults& r, const std::string& name, std::size_t point) {
  const auto it = std::find(r.scalar_names.begin(), r.scalar_names.end(), name);
  if (it == r.scalar_names.end()) throw std::out_of_range("no scalar " + name);
  return r.scalars[std::size_t(it - r.scalar_names.begin()) * r.points + point];
}

// Two results with the same statuses, scalars and rows, bit for bit.
inline bool same_bits(const jobs::sweep::SweepResults& a, const jobs::sweep::SweepResults& b) {
  if (a.status != b.status || a.scalars.size() != b.scalars.size() || a.rows.size() != b.rows.size()) return false;
  if (std::memcmp(a.scalars.data(), b.scalars.data(), a.scalars.size() * sizeof(double)) != 0) return false;
  for (std::size_t p = 0; p < a.rows.size(); ++p)
    if (a.rows[p].size() != b.rows[p].size() ||
        std::memcmp(a.rows[p].data(), b.rows[p].data(), a.rows[p].size() * sizeof(double)) != 0)
      return false;
  return true;
}

#ifdef LRCHAIN_CLI
// Runs the sweep file with `mpirun -n 2 lrchain sweep --threads 1` and reads its results file back;
// std::runtime_error with the command's stderr if it fails, or if it did not run on 2 ranks.
inline jobs::sweep::SweepResults run_sweep_on_two_ranks(const std::filesystem::path& sweep_file) {
  // CI runs as root: Open MPI refuses that unless told.
  const CommandResult r = run_command({"mpirun", "-n", "2", "--oversubscribe", "--allow-run-as-root", LRCHAIN_CLI, "sweep",
                                       "--config", sweep_file.string(), "--json", "--quiet", "--threads", "1"});
  if (r.exit_code != 0) throw std::runtime_error("mpirun -n 2 lrchain sweep failed: " + r.err);
  if (nlohmann::json::parse(r.out).at("ranks") != 2) throw std::runtime_error("mpirun -n 2 lrchain sweep ran on one rank");
  const jobs::sweep::SweepConfig c = jobs::sweep::load_sweep_config(sweep_file);
  return jobs::sweep::read_results(c.output, c, jobs::sweep::make_job(c));
}
#endif

// A short optical bright run of the paper's chain (exp1's stepper settings, 121 sites, 10 T_b).
inline constexpr const char* short_bright_base = R"(experiment = "bright"
[model]
rho = "1/3"
[bright]
branch = "optical"
theta = "pi/2"
sites = 121
periods = 10
sample_every = 0.25
spacetime_every = 1.0
snapshot_periods = [0.0]
[integrator]
stepper = "srkn11b"
dt = 0.37
)";

}  // namespace lrchain::test
