#pragma once
// A sweep spread over MPI ranks (`mpirun -n K lrchain sweep ...`, `srun lrchain sweep ...`):
// rank 0 keeps the results file and runs points too; the other ranks ask it for the next chunk of
// points whenever theirs is about to run out (asking ahead, so that a rank does not wait), and send
// back the results with the request. No static split: a rank stuck on slow points takes fewer.
// Only in builds with MPI (library lrchain_sweep_mpi).
#include <atomic>
#include <functional>

#include "lrchain/jobs/sweep/sweep_run.hpp"

namespace lrchain::jobs::sweep {

// True when the environment says this process is one of several started by mpirun or srun.
bool started_by_mpi_launcher();

// MPI for the lifetime of the object (MPI_Init_thread ... MPI_Finalize).
class MpiSession {
 public:
  MpiSession();
  ~MpiSession();
  MpiSession(const MpiSession&) = delete;
  MpiSession& operator=(const MpiSession&) = delete;
  int rank() const noexcept { return rank_; }
  int size() const noexcept { return size_; }
  int ranks_on_this_node() const noexcept { return local_size_; }
  bool threads_allowed() const noexcept { return threads_allowed_; }  // MPI_THREAD_SERIALIZED provided
  // After a rank was lost: MPI_Finalize would wait for it forever, so the destructor skips it (the
  // launcher ends the job).
  void abandon() noexcept { abandoned_ = true; }

 private:
  int rank_ = 0, size_ = 1, local_size_ = 1;
  bool threads_allowed_ = false, abandoned_ = false;
};

// Runs `step` (loading the sweep: its model file compiled into the model cache) on rank 0 first,
// then on the other ranks, which find rank 0's compiled model in the cache: one compile per sweep,
// not one per rank. Rank 0's exception is rethrown there; the other ranks run `step` all the same
// (the same bad input gives them the same error) and, if it succeeds where rank 0's failed, throw
// std::runtime_error rather than wait for a rank 0 that never starts.
void load_on_rank0_first(const MpiSession& mpi, const std::function<void()>& step);

// Runs the sweep on every rank of the session; rank 0 writes the results. The outcome is rank 0's
// (the other ranks report the points they ran).
SweepOutcome run_sweep_mpi(const MpiSession& mpi, const SweepConfig& c, const Job& job, const SweepRunOptions& o);

}  // namespace lrchain::jobs::sweep
