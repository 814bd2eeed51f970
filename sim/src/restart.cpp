// Checkpoint/restart pieces shared by the long runs (restart.hpp).
#include "restart.hpp"

#include <algorithm>
#include <cmath>
#include <fmt/format.h>

#include "lrchain/errors.hpp"
#include "lrchain/sim/output_files.hpp"

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

Checkpoint read_restart(const std::string& file, const TrajectoryIdentity& identity,
                        std::size_t state_size, double t_end) {
  Checkpoint c = read_checkpoint(file);
  check_same_trajectory(file, c, identity);
  if (c.state.size() != state_size)
    throw InvalidParameter("restart", fmt::format("checkpoint '{}' holds {} state values, this run has {}",
                                                  file, c.state.size(), state_size));
  if (!(c.t < t_end))
    throw InvalidParameter("restart", fmt::format("checkpoint '{}' is at t = {}, not before this run's end "
                                                  "t = {}: nothing left to integrate", file, c.t, t_end));
  return c;
}

Resumption resume_from_checkpoint(const std::string& file, const TrajectoryIdentity& identity, const std::string& kind,
                                  Index sites, double t_end, State& state, RunRecord& record,
                                  std::initializer_list<std::pair<const char*, double*>> accumulators,
                                  CheckpointSink& sink, std::vector<double>& times) {
  Checkpoint ck = read_restart(file, identity, state.size(), t_end);
  if (ck.record.series.names != record.series.names || ck.record.fields.size() != 1 ||
      ck.record.fields[0].sites != sites)
    throw InputError("checkpoint '" + file + "' does not hold a " + kind + " run's record");
  state = std::move(ck.state);
  record = std::move(ck.record);
  const std::filesystem::path f(file);
  for (const auto& [name, value] : accumulators) *value = ck.accumulator(f, name);
  sink.base_steps = ck.steps;
  sink.base_rhs_evaluations = ck.rhs_evaluations;
  times = times_after(times, ck.t);
  return {ck.t, ck.next_step};
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
  if (file.empty()) return false;
  const bool periodic = rhythm.due(t);
  return periodic || (at_end && t >= t_end);
}

void CheckpointSink::write(const State& s, double t, double next_step, const IntegrationStats& stats,
                           const RunRecord& record,
                           std::vector<std::pair<std::string, double>> accumulators) {
  if (file.empty()) return;
  const std::filesystem::path path(file);  // (its directory exists: checked before the run)
  Checkpoint c;
  c.identity = identity;
  c.t = t;
  c.next_step = next_step;
  c.steps = base_steps + static_cast<std::uint64_t>(stats.steps);
  c.rhs_evaluations = base_rhs_evaluations + static_cast<std::uint64_t>(stats.rhs_evaluations);
  c.accumulators = std::move(accumulators);
  c.state = s;
  write_checkpoint(path, c, record);
  ++written;
  last_time = t;
}

}  // namespace lrchain::sim
