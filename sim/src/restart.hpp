#pragma once
// Pieces the long runs (bright, drive, modulated) share for checkpoint/restart: the identity items
// every run has, reading a checkpoint for a restart, the observation times left after it, and the
// rhythm of periodic checkpoints. Private to sim/src.
#include <initializer_list>
#include <string>
#include <utility>
#include <vector>

#include "lrchain/params.hpp"
#include "lrchain/sim/checkpoint.hpp"
#include "lrchain/sim/integrator.hpp"

namespace lrchain::sim {

// Run kind, model, its parameters (alpha, delta0, kappa, rho), stepper and its settings.
TrajectoryIdentity base_identity(const std::string& run, const Params& p, const IntegratorOptions& o);

// Reads the checkpoint `file` for a restart of the run `identity` whose state has `state_size`
// values and which ends at t_end; throws InputError/InvalidParameter naming the file and what
// does not match.
Checkpoint read_restart(const std::string& file, const TrajectoryIdentity& identity,
                        std::size_t state_size, double t_end);

struct CheckpointSink;

// Where a restarted run resumes: the checkpoint's time and the step its stepper tries next.
struct Resumption {
  double t = 0;
  double next_step = 0;
};

// Continues a `kind` run ("bright", "drive", "modulated") from the checkpoint `file`: checks it
// (read_restart) and that its record has the run's series names and one field of `sites` sites,
// then moves its state and record into `state` and `record`, reads each named accumulator into
// its slot, carries the work done into `sink` and keeps the observation times from its time on.
Resumption resume_from_checkpoint(const std::string& file, const TrajectoryIdentity& identity, const std::string& kind,
                                  Index sites, double t_end, State& state, RunRecord& record,
                                  std::initializer_list<std::pair<const char*, double*>> accumulators,
                                  CheckpointSink& sink, std::vector<double>& times);

// The observation times of a run continued from a checkpoint at t0: t0, then those after it.
std::vector<double> times_after(const std::vector<double>& times, double t0);

// When periodic checkpoints are due: at the first step boundary at or after each multiple of
// `every` (0: never), so they add no observation time and leave the step sequence unchanged.
struct CheckpointRhythm {
  double every = 0;
  double next = 0;
  CheckpointRhythm() = default;
  CheckpointRhythm(double every_, double t0);
  bool due(double t);  // true (and advances) when t has reached the next multiple
};

// Where and when a run writes its checkpoints: periodically (CheckpointRhythm), at its end when
// asked, and when stopped by an interrupt.
struct CheckpointSink {
  std::string file;        // empty: no checkpoints
  std::string identity;    // TrajectoryIdentity::text() of the run
  CheckpointRhythm rhythm;
  double t_end = 0;
  bool at_end = false;     // also write one at t_end (so that the run can be extended)
  std::uint64_t base_steps = 0, base_rhs_evaluations = 0;  // work before a restart
  long written = 0;
  double last_time = -1;   // time of the last checkpoint written (< 0: none)

  // True when a checkpoint is due at the step boundary t (advances the rhythm).
  bool due(double t);
  // Writes one into its existing directory (never created: --checkpoint's directory is checked
  // before the run, --out is made by the run), recording the work so far.
  void write(const State& s, double t, double next_step, const IntegrationStats& stats,
             const RunRecord& record, std::vector<std::pair<std::string, double>> accumulators);
};

}  // namespace lrchain::sim
