// Checkpoint files as a run's checkpoint store: writing, and reading for a restart (checkpoint_files.hpp).
#include "lrchain/jobs/checkpoint/checkpoint_files.hpp"

#include <filesystem>
#include <utility>

#include <fmt/format.h>

#include "lrchain/errors.hpp"
#include "lrchain/jobs/checkpoint/checkpoint_file.hpp"

namespace lrchain::jobs {

namespace {

// The checkpoint `file` checked for the restart `r`: same trajectory, state size, a time before the
// run's end, the run's record (series names, one field of r.sites sites) and every accumulator it reads.
sim::SavedRun read_for_restart(const std::string& file, const sim::RestartRequest& r) {
  Checkpoint c = read_checkpoint(file);
  check_same_trajectory(file, c, r.identity);
  if (c.state.size() != r.state_size)
    throw InvalidParameter("restart", fmt::format("checkpoint '{}' holds {} state values, this run has {}",
                                                  file, c.state.size(), r.state_size));
  if (!(c.t < r.t_end))
    throw InvalidParameter("restart", fmt::format("checkpoint '{}' is at t = {}, not before this run's end "
                                                  "t = {}: nothing left to integrate", file, c.t, r.t_end));
  if (c.record.series.names != r.series_names || c.record.fields.size() != 1 || c.record.fields[0].sites != r.sites)
    throw InputError("checkpoint '" + file + "' does not hold a " + r.kind + " run's record");
  const std::filesystem::path f(file);
  for (const char* name : r.accumulators) c.accumulator(f, name);  // throws naming a missing one
  return {{c.t, c.next_step, c.steps, c.rhs_evaluations, std::move(c.accumulators)}, std::move(c.state),
          std::move(c.record)};
}

}  // namespace

sim::CheckpointStore checkpoint_files(const std::string& checkpoint_file, const std::string& restart_file) {
  sim::CheckpointStore store;
  if (!checkpoint_file.empty())
    store.save = [path = std::filesystem::path(checkpoint_file)](const sim::TrajectoryIdentity& identity,
                                                                 const sim::RunProgress& progress,
                                                                 const sim::State& state, const sim::RunRecord& record) {
      write_checkpoint(path, identity.text(), progress, state, record);
    };
  if (!restart_file.empty())
    store.load = [restart_file](const sim::RestartRequest& r) { return read_for_restart(restart_file, r); };
  return store;
}

}  // namespace lrchain::jobs
