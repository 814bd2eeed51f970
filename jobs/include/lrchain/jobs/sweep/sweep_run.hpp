#pragma once
// Running a sweep: threads (OpenMP, dynamic scheduling) take points from a queue, run them in-process
// (sweep/job.hpp) and hand the results to the one keeper of the results file, which rewrites it at
// checkpoints (temporary name + rename), reports progress and resumes from an earlier file.
// The queue is local (one process) or spread over MPI ranks (sweep/mpi_sweep.hpp); the results do
// not depend on how points are spread: each point's run depends on its parameters only.
#include <atomic>
#include <chrono>
#include <cstddef>
#include <filesystem>
#include <functional>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

#include "lrchain/jobs/sweep/job.hpp"
#include "lrchain/jobs/sweep/progress.hpp"
#include "lrchain/jobs/sweep/results_file.hpp"
#include "lrchain/jobs/sweep/sweep_config.hpp"

namespace lrchain::jobs::sweep {

struct SweepRunOptions {
  int threads = 0;                           // per process; 0: OpenMP's default
  bool retry_failed = false;                 // rerun points a resumed file records as failed
  const std::atomic<bool>* stop = nullptr;   // set (SIGINT/SIGTERM): finish no more points, write, return
  int (*stop_signal)() = nullptr;            // the signal that set `stop` (0 or absent: unknown)
  bool progress = true;                      // progress on stderr
  // Called (from the thread that finished a point, under the results' lock) with the points finished
  // in all (including those resumed) and the sweep's points, and once more at the end: a front
  // end's own display (lrchain.sweep's bar). Empty: none.
  std::function<void(std::size_t done, std::size_t total)> on_progress;
};

// Where a process's threads get points and leave results. Both calls are thread-safe.
class PointQueue {
 public:
  virtual ~PointQueue() = default;
  virtual std::optional<std::size_t> next() = 0;
  virtual void finished(std::size_t point, const JobResult& r) = 0;
};

// Runs points from `queue` on `threads` threads until it is empty or `stop` is set (a point
// stopped part-way is not handed over).
void run_points(const Job& job, const SweepConfig& c, PointQueue& queue, int threads,
                const std::atomic<bool>* stop);

// The writer's side: the results in memory, the points still to run, checkpoints and progress.
class ResultsKeeper {
 public:
  // Resumes from c.output when it exists (InputError naming what changed if it belongs to another
  // sweep, or the first damaged point); refuses a side file of the user's (side_files.hpp); creates
  // the output's directory.
  ResultsKeeper(const SweepConfig& c, const Job& job, const SweepRunOptions& o);
  const std::vector<std::size_t>& todo() const noexcept { return todo_; }  // in point order
  std::size_t resumed() const noexcept { return resumed_; }                // finished before this run
  // Records one point (thread-safe); rewrites the file when a checkpoint is due.
  void record(std::size_t point, const JobResult& r);
  // Writes the results file and, for a small sweep, the CSV view; ends the progress line.
  void write_final();
  const SweepResults& results() const noexcept { return results_; }
  std::filesystem::path csv_path() const;
  std::filesystem::path rows_csv_path() const;  // the rows' CSV view (jobs with rows)

 private:
  const SweepConfig& config_;
  SweepResults results_;
  std::vector<std::size_t> todo_;
  std::size_t resumed_ = 0;
  std::mutex mutex_;
  std::chrono::steady_clock::time_point last_write_;
  SweepProgress progress_;
  std::function<void(std::size_t, std::size_t)> on_progress_;
  std::vector<std::string> csv_files_;  // the CSV views written next to the results (side_files.hpp)
};

struct SweepOutcome {
  std::size_t points = 0, finished = 0, failed = 0, ran = 0, resumed = 0;
  bool interrupted = false;  // points are missing: a signal, here or on another rank, or a lost rank
  int stop_signal = 0;       // the signal that stopped this or another rank (0: none or unknown)
  int lost_ranks = 0;        // MPI ranks that never sent their last results
  std::size_t missing = 0;   // points not run
  std::vector<std::size_t> missing_points;  // the first 1000 of them, in order
  double seconds = 0;
};
// Summary of a keeper after its run.
SweepOutcome outcome_of(const ResultsKeeper& keeper, std::size_t ran, bool interrupted, double seconds);

// The whole sweep in this process.
SweepOutcome run_sweep(const SweepConfig& c, const Job& job, const SweepRunOptions& o);

}  // namespace lrchain::jobs::sweep
