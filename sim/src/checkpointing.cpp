// Checkpoint/restart pieces shared by the long runs, through a CheckpointStore (checkpointing.hpp).
#include "checkpointing.hpp"

#include <algorithm>
#include <cmath>

#include "lrchain/errors.hpp"

namespace lrchain::sim {

TrajectoryIdentity base_identity(const std::string& run, const Params& p, const IntegratorOptions& o) {
  TrajectoryIdentity id;
  id.add("run", run);
  id.add("model", "locally_resonant_granular_chain");
  id.add("alpha", p.alpha);
  id.add("delta0", p.delta0);
  id.add("kappa", p.kappa);
  id.add("rho", p.rho);
  id.add("stepper", std::string(to_string(o.stepper)));
  id.add("dt", o.dt);
  if (!is_symplectic(o.stepper)) {  // the fixed-step steppers have no tolerances
    id.add("abs_tol", o.abs_tol);
    id.add("rel_tol", o.rel_tol);
  }
  return id;
}

void require_checkpoint_store(const RunControl& control, const std::string& checkpoint_file,
                              const std::string& restart_file) {
  if (!checkpoint_file.empty() && !control.checkpoints.save)
    throw InvalidParameter("checkpoint", "'" + checkpoint_file + "' needs a checkpoint store in RunControl "
                                         "(sim writes no files: jobs::with_checkpoint_files gives one)");
  if (!restart_file.empty() && !control.checkpoints.load)
    throw InvalidParameter("restart", "'" + restart_file + "' needs a checkpoint store in RunControl "
                                      "(sim reads no files: jobs::with_checkpoint_files gives one)");
}

Resumption resume_from_checkpoint(const CheckpointStore& store, const TrajectoryIdentity& identity, const char* kind,
                                  Index sites, double t_end, State& state, RunRecord& record,
                                  std::initializer_list<std::pair<const char*, double*>> accumulators,
                                  CheckpointSink& sink, std::vector<double>& times) {
  RestartRequest request{identity, kind, state.size(), sites, record.series.names, t_end, {}};
  for (const auto& [name, value] : accumulators) request.accumulators.push_back(name);
  SavedRun saved = store.load(request);
  state = std::move(saved.state);
  record = std::move(saved.record);
  const RunProgress& p = saved.progress;
  for (const auto& [name, value] : accumulators)
    for (const auto& [k, v] : p.accumulators)
      if (k == name) *value = v;  // (the store's load checked that each is there)
  sink.base_steps = p.steps;
  sink.base_rhs_evaluations = p.rhs_evaluations;
  times = times_after(times, p.t);
  return {p.t, p.next_step};
}

std::vector<double> times_after(const std::vector<double>& times, double t0) {
  std::vector<double> out{t0};
  for (double t : times)
    if (t > t0) out.push_back(t);
  return out;
}

CheckpointRhythm::CheckpointRhythm(double every_, double t0) : every(every_) {
  if (every > 0) next = (std::floor(t0 / every) + 1) * every;
}

bool CheckpointRhythm::due(double t) {
  if (!(every > 0) || t < next * (1 - 1e-12)) return false;
  next = (std::floor(t / every * (1 + 1e-12)) + 1) * every;
  return true;
}

bool CheckpointSink::due(double t) {
  if (!saves()) return false;
  const bool periodic = rhythm.due(t);
  return periodic || (at_end && t >= t_end);
}

void CheckpointSink::write(const State& s, double t, double next_step, const IntegrationStats& stats,
                           const RunRecord& record,
                           std::vector<std::pair<std::string, double>> accumulators) {
  if (!saves()) return;
  RunProgress p;
  p.t = t;
  p.next_step = next_step;
  p.steps = base_steps + static_cast<std::uint64_t>(stats.steps);
  p.rhs_evaluations = base_rhs_evaluations + static_cast<std::uint64_t>(stats.rhs_evaluations);
  p.accumulators = std::move(accumulators);
  store->save(*identity, p, s, record);
  ++written;
  last_time = t;
}

}  // namespace lrchain::sim
