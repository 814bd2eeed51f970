#pragma once
// One point of a parameter study, run in-process: a simulate job ("bright", "drive", "modulated")
// described by a base experiment config (examples/*.toml), a simulate job of a model file ("bright",
// "ring"; any `lrchain simulate --config` file with `model = "models/x.toml"`, the model loaded once
// per job through the one model loader, jobs::ModelSource), or a study job ("dark continue",
// "regime intervals"; sweep/study_jobs.hpp) described by its own base config, and parameter
// overrides ("bright.theta", "model.rho", "dark.edge_offset", ... any number or integer key of the
// job's schema; "parameters.b", ... any parameter of a model file). No process is spawned and nothing is written: the run yields the job's summary
// scalars, for some jobs a table of rows (one per branch point, per interval), and a status.
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "lrchain/config/strict_toml.hpp"
#include "lrchain/jobs/model_source.hpp"
#include "lrchain/sim/resonant_chain_bright_run.hpp"
#include "lrchain/sim/run_control.hpp"

namespace lrchain::jobs::sweep {

// What became of one point. `missing` (not run yet) is what a results file holds before the run.
enum class PointStatus : std::int8_t { missing = 0, ok = 1, blew_up = 2, numerical_failure = 3, invalid = 4 };
const char* to_string(PointStatus s);
// "0 missing, 1 ok, 2 blew_up, 3 numerical_failure, 4 invalid" (the results file's legend).
std::string status_legend();

struct JobResult {
  PointStatus status = PointStatus::missing;  // missing: interrupted before the end
  std::string reason;                         // why it failed (empty when ok)
  std::vector<double> scalars;                // in the order of Job::scalar_names(); NaN: none
  double wall_seconds = 0;
  std::vector<double> rows;                   // jobs with rows (Job::row_names()): row-major, in order
};

// (parameter, value) pairs set on top of the base config for one point.
using Overrides = std::vector<std::pair<std::string, double>>;

// Buffers one thread reuses from point to point (bright runs: their lattice, state, observers and
// record), so that a sweep allocates per thread, not per point.
struct JobWorkspace {
  sim::BrightWorkspace bright;
};

class Job {
 public:
  // The job of a base experiment config (its `experiment` key). The document is checked against
  // its kind's schema here (ConfigError naming file, line and key). A model-file base has its model
  // and its lattice kernels loaded here, once (jobs::ModelSource: a shipped model's bytes, else the
  // file compiled by `compiler`; null: shipped model files only).
  explicit Job(lrchain::config::Document base, std::shared_ptr<const ModelCompiler> compiler = nullptr);

  const std::string& kind() const noexcept { return kind_; }
  const lrchain::config::Document& base() const noexcept { return base_; }
  // The loaded model of a model-file base (shared by copies of the job; its lattice() already
  // loaded, so threads only read it), or nullptr.
  const ModelSource* model_source() const noexcept { return model_.get(); }
  // The summary scalars each point yields (max_Ex, centre_speed, blew_up, ...).
  const std::vector<std::string>& scalar_names() const noexcept { return scalar_names_; }
  // The columns of the job's rows (empty: the job has none), and what their codes mean.
  const std::vector<std::string>& row_names() const noexcept { return row_names_; }
  std::string rows_legend() const;
  // The parameters a point may override: "table.key" for every number or integer key.
  std::vector<std::string> parameters() const;
  bool has_parameter(const std::string& parameter) const;
  // A parameter whose key was renamed ("bright.N"): its old and new "table.key" and the note of
  // the schema's RenamedKey; nullopt for any other name.
  std::optional<lrchain::config::RenamedKey> renamed_parameter(const std::string& parameter) const;

  // Runs one point. Never throws for a bad point: a value the config layer or the run's checks
  // refuse gives status `invalid`, a blow-up `blew_up`; `control.stop` ends the run early with
  // status `missing`.
  JobResult run(const Overrides& overrides, const sim::RunControl& control = {}) const;
  // The same run in the thread's `workspace` (the same numbers, bit for bit).
  JobResult run(const Overrides& overrides, const sim::RunControl& control, JobWorkspace& workspace) const;

 private:
  lrchain::config::Document base_;
  std::string kind_;
  std::shared_ptr<const ModelSource> model_;  // model-file bases: loaded once, shared by every point
  std::vector<std::string> scalar_names_, row_names_;
};

// The kind of a base config: its `experiment` key, one of the simulate kinds or the study kinds
// (ConfigError naming the file and line otherwise).
std::string job_kind(const lrchain::config::Document& doc);
// The jobs a sweep can run.
std::vector<std::string> job_kinds();

}  // namespace lrchain::jobs::sweep
