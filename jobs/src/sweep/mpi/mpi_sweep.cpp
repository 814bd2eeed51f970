// A sweep over MPI ranks (sweep/mpi_sweep.hpp): rank 0 hands out chunks of points on request and
// keeps the results; every rank runs points on its threads.
#include "lrchain/jobs/sweep/mpi_sweep.hpp"

#include <mpi.h>
#include <omp.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <deque>
#include <exception>
#include <functional>
#include <mutex>
#include <optional>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

namespace lrchain::jobs::sweep {

using namespace lrchain::sim;  // the numerics this job layer runs

namespace {

constexpr int tag_request = 1;  // worker -> 0: results so far, and whether it wants more points
constexpr int tag_chunk = 2;    // 0 -> worker: the next points (none: no more)

// Appends/reads plain values to/from a byte buffer (the messages' wire format; all ranks run the
// same binary on the same kind of machine).
template <class T>
void put(std::vector<char>& b, const T& v) {
  const std::size_t at = b.size();
  b.resize(at + sizeof(T));
  std::memcpy(b.data() + at, &v, sizeof(T));
}
template <class T>
T take(const std::vector<char>& b, std::size_t& at) {
  T v;
  std::memcpy(&v, b.data() + at, sizeof(T));
  at += sizeof(T);
  return v;
}

// A request: want-more flag, the signal that stopped the sender (0: none, -1: stopped, signal
// unknown), then (point, status, wall time, scalars, reason, rows) per finished point.
std::vector<char> pack_request(bool want_more, int stopped_by, const std::vector<std::pair<std::size_t, JobResult>>& done) {
  std::vector<char> b;
  put<std::uint8_t>(b, want_more ? 1 : 0);
  put<std::int32_t>(b, stopped_by);
  put<std::uint64_t>(b, done.size());
  for (const auto& [point, r] : done) {
    put<std::uint64_t>(b, point);
    put<std::int8_t>(b, std::int8_t(r.status));
    put<double>(b, r.wall_seconds);
    put<std::uint64_t>(b, r.scalars.size());
    for (double v : r.scalars) put<double>(b, v);
    put<std::uint64_t>(b, r.reason.size());
    b.insert(b.end(), r.reason.begin(), r.reason.end());
    put<std::uint64_t>(b, r.rows.size());
    for (double v : r.rows) put<double>(b, v);
  }
  return b;
}

std::vector<char> receive_bytes(int source, int tag, MPI_Status& status) {
  MPI_Probe(source, tag, MPI_COMM_WORLD, &status);
  int bytes = 0;
  MPI_Get_count(&status, MPI_BYTE, &bytes);
  std::vector<char> b(static_cast<std::size_t>(bytes));
  MPI_Recv(b.data(), bytes, MPI_BYTE, status.MPI_SOURCE, tag, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
  return b;
}

// Rank 0: its own threads take single points; requests from the other ranks are served whenever
// one of its threads asks for a point or returns a result, and while it waits at the end.
class Coordinator final : public PointQueue {
 public:
  Coordinator(ResultsKeeper& keeper, int ranks, const std::atomic<bool>* stop)
      : keeper_(keeper), ranks_(ranks), stop_(stop) {}

  std::optional<std::size_t> next() override {
    std::lock_guard<std::mutex> lock(mutex_);
    serve();
    if (stopped() || next_ >= keeper_.todo().size()) return std::nullopt;
    return keeper_.todo()[next_++];
  }
  void finished(std::size_t point, const JobResult& r) override {
    keeper_.record(point, r);
    std::lock_guard<std::mutex> lock(mutex_);
    ++ran_;
    serve();
  }
  // Serves until every other rank has sent its last results. Once this rank is stopped by a signal
  // (mpirun passes SIGTERM on and kills 1 s later; a rank that died sends nothing), it waits at
  // most `grace` for them, so that the results so far are written in time; the ranks still silent
  // then are counted as lost.
  void drain(std::chrono::milliseconds grace = std::chrono::milliseconds(300)) {
    std::optional<std::chrono::steady_clock::time_point> give_up;
    for (;;) {
      {
        std::lock_guard<std::mutex> lock(mutex_);
        serve();
        if (finals_ == ranks_ - 1) return;
        if (stop_ && stop_->load() && !give_up) give_up = std::chrono::steady_clock::now() + grace;
        if (give_up && std::chrono::steady_clock::now() >= *give_up) {
          lost_ = ranks_ - 1 - finals_;
          return;
        }
      }
      std::this_thread::sleep_for(std::chrono::milliseconds(1));
    }
  }
  std::size_t ran() const { return ran_; }
  int lost_ranks() const { return lost_; }
  // The signal another rank reported it was stopped by (0: none; -1: stopped, signal unknown).
  int remote_stop() const { return remote_stop_; }

 private:
  bool stopped() const { return (stop_ && stop_->load()) || remote_stop_ != 0; }

  // Handles every pending request (called with mutex_ held).
  void serve() {
    for (;;) {
      int pending = 0;
      MPI_Status status;
      MPI_Iprobe(MPI_ANY_SOURCE, tag_request, MPI_COMM_WORLD, &pending, &status);
      if (!pending) return;
      const std::vector<char> b = receive_bytes(status.MPI_SOURCE, tag_request, status);
      std::size_t at = 0;
      const bool want_more = take<std::uint8_t>(b, at) != 0;
      // A rank stopped by a signal stops the sweep: no more points are handed out, here or there.
      if (const auto stopped_by = take<std::int32_t>(b, at); stopped_by != 0 && remote_stop_ == 0) remote_stop_ = stopped_by;
      const auto count = take<std::uint64_t>(b, at);
      for (std::uint64_t k = 0; k < count; ++k) {
        const auto point = std::size_t(take<std::uint64_t>(b, at));
        JobResult r;
        r.status = PointStatus(take<std::int8_t>(b, at));
        r.wall_seconds = take<double>(b, at);
        r.scalars.resize(take<std::uint64_t>(b, at));
        for (double& v : r.scalars) v = take<double>(b, at);
        const auto length = take<std::uint64_t>(b, at);
        r.reason.assign(b.data() + at, length);
        at += length;
        r.rows.resize(take<std::uint64_t>(b, at));
        for (double& v : r.rows) v = take<double>(b, at);
        keeper_.record(point, r);
        ++ran_;
      }
      if (!want_more) {
        ++finals_;
        continue;
      }
      // Guided chunks: large while many points remain, single points near the end.
      const std::size_t remaining = stopped() ? 0 : keeper_.todo().size() - next_;
      const std::size_t chunk = std::min<std::size_t>(remaining, std::clamp<std::size_t>(remaining / (4 * std::size_t(ranks_)), 1, 16));
      std::vector<std::uint64_t> points(keeper_.todo().begin() + std::ptrdiff_t(next_),
                                        keeper_.todo().begin() + std::ptrdiff_t(next_ + chunk));
      next_ += chunk;
      MPI_Send(points.data(), int(points.size()), MPI_UINT64_T, status.MPI_SOURCE, tag_chunk, MPI_COMM_WORLD);
    }
  }

  ResultsKeeper& keeper_;
  int ranks_;
  const std::atomic<bool>* stop_;
  std::mutex mutex_;
  std::size_t next_ = 0, ran_ = 0;
  int finals_ = 0, lost_ = 0, remote_stop_ = 0;
};

// Ranks > 0: points come from rank 0 in chunks; the next chunk is asked for when the last point
// of the current one is taken, so it arrives while that point runs.
class Worker final : public PointQueue {
 public:
  Worker(const std::atomic<bool>* stop, int (*stop_signal)()) : stop_(stop), stop_signal_(stop_signal) {}
  std::optional<std::size_t> next() override {
    std::lock_guard<std::mutex> lock(mutex_);
    if (local_.empty() && !no_more_) {
      if (!asked_) ask();
      wait_for_chunk();
    }
    if (local_.empty()) return std::nullopt;
    const std::size_t p = local_.front();
    local_.pop_front();
    if (local_.empty() && !no_more_ && !asked_) ask();
    return p;
  }
  void finished(std::size_t point, const JobResult& r) override {
    std::lock_guard<std::mutex> lock(mutex_);
    done_.emplace_back(point, r);
    ++ran_;
  }
  // The last message: the results not sent yet (after the answer to a request still open).
  void finish() {
    std::lock_guard<std::mutex> lock(mutex_);
    if (asked_) wait_for_chunk();
    const auto b = pack_request(false, stopped_by(), done_);
    MPI_Send(b.data(), int(b.size()), MPI_BYTE, 0, tag_request, MPI_COMM_WORLD);
    done_.clear();
  }
  std::size_t ran() const { return ran_; }

 private:
  void ask() {
    const auto b = pack_request(true, stopped_by(), done_);
    MPI_Send(b.data(), int(b.size()), MPI_BYTE, 0, tag_request, MPI_COMM_WORLD);
    done_.clear();
    asked_ = true;
  }
  void wait_for_chunk() {
    MPI_Status status;
    MPI_Probe(0, tag_chunk, MPI_COMM_WORLD, &status);
    int count = 0;
    MPI_Get_count(&status, MPI_UINT64_T, &count);
    std::vector<std::uint64_t> points(static_cast<std::size_t>(count));
    MPI_Recv(points.data(), count, MPI_UINT64_T, 0, tag_chunk, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
    asked_ = false;
    if (points.empty()) no_more_ = true;
    local_.insert(local_.end(), points.begin(), points.end());
  }

  // What this rank tells rank 0 about its stop flag (pack_request).
  int stopped_by() const {
    if (!stop_ || !stop_->load()) return 0;
    const int signal_number = stop_signal_ ? stop_signal_() : 0;
    return signal_number != 0 ? signal_number : -1;
  }

  const std::atomic<bool>* stop_;
  int (*stop_signal_)();
  std::mutex mutex_;
  std::deque<std::size_t> local_;
  std::vector<std::pair<std::size_t, JobResult>> done_;
  bool asked_ = false, no_more_ = false;
  std::size_t ran_ = 0;
};

}  // namespace

bool started_by_mpi_launcher() {
  // mpirun (Open MPI), and srun with --mpi=pmi2 or --mpi=pmix.
  for (const char* v : {"OMPI_COMM_WORLD_SIZE", "PMI_SIZE", "PMIX_RANK"})
    if (std::getenv(v)) return true;
  return false;
}

MpiSession::MpiSession() {
  int provided = 0;
  MPI_Init_thread(nullptr, nullptr, MPI_THREAD_SERIALIZED, &provided);
  threads_allowed_ = provided >= MPI_THREAD_SERIALIZED;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank_);
  MPI_Comm_size(MPI_COMM_WORLD, &size_);
  MPI_Comm node;
  MPI_Comm_split_type(MPI_COMM_WORLD, MPI_COMM_TYPE_SHARED, rank_, MPI_INFO_NULL, &node);
  MPI_Comm_size(node, &local_size_);
  MPI_Comm_free(&node);
}

MpiSession::~MpiSession() {
  if (!abandoned_) MPI_Finalize();
}

void load_on_rank0_first(const MpiSession& mpi, const std::function<void()>& step) {
  int rank0_loaded = 1;
  if (mpi.rank() == 0) {
    std::exception_ptr failure;
    try {
      step();
    } catch (...) {
      failure = std::current_exception();
      rank0_loaded = 0;
    }
    MPI_Bcast(&rank0_loaded, 1, MPI_INT, 0, MPI_COMM_WORLD);
    if (failure) std::rethrow_exception(failure);
    return;
  }
  MPI_Bcast(&rank0_loaded, 1, MPI_INT, 0, MPI_COMM_WORLD);
  step();
  if (rank0_loaded == 0)
    throw std::runtime_error("rank " + std::to_string(mpi.rank()) + ": rank 0 could not load the sweep (its error is on its stderr)");
}

SweepOutcome run_sweep_mpi(const MpiSession& mpi, const SweepConfig& c, const Job& job, const SweepRunOptions& o) {
  const auto start = std::chrono::steady_clock::now();
  // Threads per rank: as asked, else the cores shared among the ranks on this node.
  int threads = o.threads > 0 ? o.threads : std::max(1, omp_get_num_procs() / std::max(1, mpi.ranks_on_this_node()));
  if (!mpi.threads_allowed()) threads = 1;
  auto seconds = [&] { return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(); };
  if (mpi.rank() == 0) {
    // The keeper refuses a results file or side file before any point runs (exit 2): every rank
    // learns it here, so that none waits for points that never come and all finalize.
    std::optional<ResultsKeeper> kept;
    std::exception_ptr refusal;
    try {
      kept.emplace(c, job, o);
    } catch (...) {
      refusal = std::current_exception();
    }
    int go = refusal ? 0 : 1;
    MPI_Bcast(&go, 1, MPI_INT, 0, MPI_COMM_WORLD);
    if (refusal) std::rethrow_exception(refusal);
    ResultsKeeper& keeper = *kept;
    Coordinator queue(keeper, mpi.size(), o.stop);
    run_points(job, c, queue, threads, o.stop);
    queue.drain();
    keeper.write_final();
    // Every point handed out comes back unless a rank was stopped or lost: then points are missing
    // and the sweep says so, whichever rank it was.
    const bool interrupted = keeper.results().finished() < keeper.results().points;
    // A lost rank would never reach the barrier.
    if (queue.lost_ranks() == 0) MPI_Barrier(MPI_COMM_WORLD);
    SweepOutcome out = outcome_of(keeper, queue.ran(), interrupted, seconds());
    out.lost_ranks = queue.lost_ranks();
    const int here = o.stop && o.stop->load() && o.stop_signal ? o.stop_signal() : 0;
    out.stop_signal = here != 0 ? here : std::max(queue.remote_stop(), 0);
    return out;
  }
  int go = 0;
  MPI_Bcast(&go, 1, MPI_INT, 0, MPI_COMM_WORLD);
  if (!go) return SweepOutcome{};  // rank 0 refused the sweep and says why
  Worker queue(o.stop, o.stop_signal);
  run_points(job, c, queue, threads, o.stop);
  queue.finish();
  MPI_Barrier(MPI_COMM_WORLD);
  SweepOutcome out;
  out.ran = queue.ran();
  out.interrupted = o.stop && o.stop->load();
  if (out.interrupted && o.stop_signal) out.stop_signal = o.stop_signal();
  out.seconds = seconds();
  return out;
}

}  // namespace lrchain::jobs::sweep
