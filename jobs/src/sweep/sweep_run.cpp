// Running a sweep's points on threads and keeping its results file (sweep/sweep_run.hpp).
#include "lrchain/jobs/sweep/sweep_run.hpp"

#include <omp.h>

#include <cmath>

#include "lrchain/errors.hpp"
#include "lrchain/jobs/sweep/side_files.hpp"

namespace lrchain::jobs::sweep {

using namespace lrchain::sim;  // the numerics this job layer runs

namespace {

// Points of this process, handed out in order to whichever thread asks next.
class LocalQueue final : public PointQueue {
 public:
  explicit LocalQueue(ResultsKeeper& keeper) : keeper_(keeper) {}
  std::optional<std::size_t> next() override {
    const std::size_t i = next_.fetch_add(1);
    if (i >= keeper_.todo().size()) return std::nullopt;
    return keeper_.todo()[i];
  }
  void finished(std::size_t point, const JobResult& r) override {
    keeper_.record(point, r);
    ran_.fetch_add(1);
  }
  std::size_t ran() const { return ran_.load(); }

 private:
  ResultsKeeper& keeper_;
  std::atomic<std::size_t> next_{0}, ran_{0};
};

}  // namespace

void run_points(const Job& job, const SweepConfig& c, PointQueue& queue, int threads, const std::atomic<bool>* stop) {
  RunControl control;
  control.stop = stop;
  const int team = threads > 0 ? threads : omp_get_max_threads();
  // Each thread takes the next point when it is free (dynamic scheduling, one point at a time) and
  // runs it in its own workspace.
#pragma omp parallel num_threads(team)
  {
    JobWorkspace workspace;  // this thread's buffers, reused by each of its points
    while (!control.stop_requested()) {
      const auto point = queue.next();
      if (!point) break;
      const JobResult r = job.run(c.overrides(*point), control, workspace);
      if (r.status == PointStatus::missing) break;  // stopped part-way: not a result
      queue.finished(*point, r);
    }
  }
}

ResultsKeeper::ResultsKeeper(const SweepConfig& c, const Job& job, const SweepRunOptions& o)
    : config_(c),
      results_(job, c.points()),
      last_write_(std::chrono::steady_clock::now()),
      progress_(0, 0, false),
      on_progress_(o.on_progress),
      csv_files_(csv_view_files(c, job)) {
  check_side_files(c, job);
  std::error_code ec;
  if (std::filesystem::exists(c.output, ec)) {
    if (std::filesystem::is_directory(c.output, ec))
      throw InputError("output '" + c.output.string() + "' is a directory; give a file name");
    results_ = read_results(c.output, c, job);
  } else if (c.output.has_parent_path()) {
    std::filesystem::create_directories(c.output.parent_path(), ec);
    if (ec) throw InputError("cannot create the directory of output '" + c.output.string() + "': " + ec.message());
  }
  for (std::size_t p = 0; p < results_.points; ++p) {
    const auto s = PointStatus(results_.status[p]);
    const bool rerun = s == PointStatus::missing || (o.retry_failed && s != PointStatus::ok);
    if (rerun) {
      todo_.push_back(p);
      if (s != PointStatus::missing) results_.set(p, JobResult{PointStatus::missing, "", std::vector<double>(results_.scalar_names.size(), std::nan("")), 0, {}});
    }
  }
  resumed_ = results_.finished();
  progress_ = SweepProgress(results_.points, resumed_, o.progress);
}

void ResultsKeeper::record(std::size_t point, const JobResult& r) {
  std::lock_guard<std::mutex> lock(mutex_);
  results_.set(point, r);
  const std::size_t done = results_.finished();
  progress_.update(done);
  if (on_progress_) on_progress_(done, results_.points);
  const auto now = std::chrono::steady_clock::now();
  if (std::chrono::duration<double>(now - last_write_).count() >= config_.checkpoint_seconds) {
    write_results(config_.output, config_, results_);
    last_write_ = std::chrono::steady_clock::now();
  }
}

std::filesystem::path ResultsKeeper::csv_path() const {
  auto p = config_.output;
  return p.replace_extension(".csv");
}

std::filesystem::path ResultsKeeper::rows_csv_path() const {
  auto p = config_.output;
  return p.replace_extension(".rows.csv");
}

void ResultsKeeper::write_final() {
  std::lock_guard<std::mutex> lock(mutex_);
  write_results(config_.output, config_, results_);
  if (!csv_files_.empty()) {
    mark_side_files_pending(config_, csv_files_);
    write_results_csv(csv_path(), config_, results_);
    if (!results_.row_names.empty()) write_rows_csv(rows_csv_path(), config_, results_);
    record_side_files(config_, csv_files_);
  }
  progress_.finish(results_.finished());
  if (on_progress_) on_progress_(results_.finished(), results_.points);
}

SweepOutcome outcome_of(const ResultsKeeper& keeper, std::size_t ran, bool interrupted, double seconds) {
  SweepOutcome o;
  o.points = keeper.results().points;
  o.finished = keeper.results().finished();
  o.failed = keeper.results().failed();
  o.ran = ran;
  o.resumed = keeper.resumed();
  o.interrupted = interrupted;
  o.seconds = seconds;
  const auto& status = keeper.results().status;
  for (std::size_t p = 0; p < status.size(); ++p) {
    if (status[p] != std::int8_t(PointStatus::missing)) continue;
    ++o.missing;
    if (o.missing_points.size() < 1000) o.missing_points.push_back(p);
  }
  return o;
}

SweepOutcome run_sweep(const SweepConfig& c, const Job& job, const SweepRunOptions& o) {
  const auto start = std::chrono::steady_clock::now();
  ResultsKeeper keeper(c, job, o);
  LocalQueue queue(keeper);
  run_points(job, c, queue, o.threads, o.stop);
  keeper.write_final();
  const bool interrupted = keeper.results().finished() < keeper.results().points && o.stop && o.stop->load();
  SweepOutcome out = outcome_of(keeper, queue.ran(), interrupted,
                                std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
  if (interrupted && o.stop_signal) out.stop_signal = o.stop_signal();
  return out;
}

}  // namespace lrchain::jobs::sweep
