// `lrchain sweep --config sweep.toml`: one job over a grid or list of parameter points, in-process,
// on threads and (in builds with MPI, under mpirun or srun) over ranks; results in one HDF5 file.
#include <string>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <iostream>
#include <memory>
#include <stdexcept>

#include "commands.hpp"
#include "help_text.hpp"
#include "lrchain/errors.hpp"
#include "lrchain/provenance_json.hpp"
#include "lrchain/jobs/sweep/side_files.hpp"
#include "lrchain/jobs/sweep/sweep_config.hpp"
#include "lrchain/jobs/sweep/sweep_figure.hpp"
#include "lrchain/jobs/sweep/sweep_memory.hpp"
#include "lrchain/jobs/sweep/sweep_run.hpp"
#include "model_option.hpp"
#include "options.hpp"
#include "stop_signals.hpp"
#ifdef LRCHAIN_WITH_MPI
#include "lrchain/jobs/sweep/mpi_sweep.hpp"
#endif

namespace lrchain::cli {

namespace {

struct SweepArguments {
  std::string config, output;
  int threads = 0;
  bool retry_failed = false, quiet = false, compact = false;
};

// Loads and checks everything, runs the sweep (resuming from its results file), prints a JSON
// summary; an interrupted sweep ends with exit 130/143 after its results so far are written.
void run_sweep_command(const SweepArguments& a) {
  jobs::sweep::SweepConfig c;
  // The sweep file, its base and the base's model file (a user's file compiled into the model cache).
  const auto load = [&] { c = jobs::sweep::load_sweep_config(a.config, jobs::sweep::launcher_ranks_on_this_node(), model_compiler()); };
#ifdef LRCHAIN_WITH_MPI
  std::unique_ptr<jobs::sweep::MpiSession> mpi;
  if (jobs::sweep::started_by_mpi_launcher()) mpi = std::make_unique<jobs::sweep::MpiSession>();
  if (mpi)
    jobs::sweep::load_on_rank0_first(*mpi, load);  // one compile of the model file, by rank 0
  else
    load();
#else
  load();
#endif
  if (!a.output.empty()) {
    if (const std::string problem = jobs::sweep::output_problem(a.output, !c.figure.empty()); !problem.empty())
      throw InvalidParameter("--output", problem);
    c.output = a.output;
  }
  const jobs::sweep::Job job = jobs::sweep::make_job(c);
  jobs::sweep::SweepRunOptions o;
  o.threads = a.threads;
  o.retry_failed = a.retry_failed;
  o.progress = !a.quiet;
  StopSignals signals;
  o.stop = StopSignals::flag();
  o.stop_signal = &StopSignals::received;
  jobs::sweep::SweepOutcome r;
  int rank = 0, ranks = 1;
#ifdef LRCHAIN_WITH_MPI
  if (mpi) {
    rank = mpi->rank();
    ranks = mpi->size();
    o.progress = o.progress && rank == 0;
    r = jobs::sweep::run_sweep_mpi(*mpi, c, job, o);
    if (r.lost_ranks > 0) mpi->abandon();
  } else {
    r = jobs::sweep::run_sweep(c, job, o);
  }
#else
  r = jobs::sweep::run_sweep(c, job, o);
#endif
  if (rank != 0) {
    // A rank stopped by a signal ends as rank 0 does (rank 0 reports the sweep).
    if (r.interrupted && StopSignals::received() != 0)
      throw Interrupted(StopSignals::received(), fmt::format("rank {} interrupted by {}; rank 0 wrote the results so far", rank,
                                                             StopSignals::name(StopSignals::received())));
    return;
  }
  nlohmann::json j;
  j["figures"] = nlohmann::json::array();
  if (!r.interrupted) j["figures"] = jobs::sweep::write_requested_figure(c, job);
  j["name"] = c.name;
  j["job"] = c.job;
  j["output"] = c.output.string();
  auto csv = c.output;
  const bool small = c.points() <= c.csv_max_points;
  j["csv"] = small ? nlohmann::json(csv.replace_extension(".csv").string()) : nlohmann::json(nullptr);
  j["rows_csv"] = small && !job.row_names().empty() ? nlohmann::json(csv.replace_extension(".rows.csv").string())
                                                    : nlohmann::json(nullptr);
  j["points"] = r.points;
  j["finished"] = r.finished;
  j["failed"] = r.failed;
  j["ran"] = r.ran;
  j["resumed"] = r.resumed;
  j["ranks"] = ranks;
  j["interrupted"] = r.interrupted;
  j["missing"] = r.missing;
  j["missing_points"] = r.missing_points;  // the first 1000 points not run (status "missing" in the results)
  j["lost_ranks"] = r.lost_ranks;
  j["seconds"] = r.seconds;
  j["provenance"] = provenance_json();
  std::cout << (a.compact ? j.dump() : j.dump(2)) << std::endl;
  if (r.interrupted) {
    // A signal here or on another rank: exit 128 + signal; a rank lost without one: exit 1.
    const int signal_number = StopSignals::received() != 0 ? StopSignals::received() : r.stop_signal;
    if (signal_number <= 0)
      throw std::runtime_error(fmt::format("{} of {} points are missing: {} rank(s) stopped without sending their results; the "
                                           "results so far are in '{}'; run the same command again to continue",
                                           r.missing, r.points, r.lost_ranks, c.output.string()));
    throw Interrupted(signal_number, fmt::format("interrupted by {}{} after {} of {} points; the results so far are in '{}'; "
                                                 "run the same command again to continue",
                                                 StopSignals::name(signal_number),
                                                 StopSignals::received() != 0 ? "" : " on another rank", r.finished, r.points,
                                                 c.output.string()));
  }
}

}  // namespace

void register_sweep(CLI::App& app) {
  auto a = std::make_shared<SweepArguments>();
  auto* cmd = app.add_subcommand(
      "sweep",
      "Run one job (bright, drive, modulated, dark continue, regime intervals, wave stability, wave fate, wave standing; bright, ring, "
      "dark continue, regime intervals, the wave jobs and bright floquet|continue of model files) over a grid or list of parameter points described in a TOML "
      "file, in-process on threads (and over MPI ranks under mpirun or srun); results in one HDF5 file "
      "(and a CSV view for small sweeps). A stopped sweep continues from its results file.");
  cmd->add_option("--config", a->config, "the sweep file (docs/sweeps.md)")->required()->type_name("FILE");
  cmd->add_option("--output", a->output, "results file (default: the sweep file's `output`)")->type_name("FILE");
  add_integer(*cmd, "--threads", a->threads, 1, 4096, "threads per process (default: all cores, shared among the ranks of a node)");
  cmd->add_flag("--retry-failed", a->retry_failed, "when resuming, run the points recorded as failed again");
  cmd->add_flag("--quiet", a->quiet, "no progress on stderr");
  cmd->add_flag("--json", a->compact, "print the JSON summary on one line (default: indented)");
  add_examples(*cmd, {"lrchain sweep --config examples/sweeps/regime_intervals_rho.toml --threads 2"});
  cmd->callback([a] { run_sweep_command(*a); });
}

}  // namespace lrchain::cli
