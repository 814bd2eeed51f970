#pragma once
// The sweep jobs whose base is a model-file simulate config (model_experiment_config.hpp): "bright"
// (the NLS bright breather on the model's lattice) and "ring" (plane waves and a packet on a
// periodic ring), each point run through the same job function as `lrchain simulate --config`
// (jobs/simulate/model_simulate_job.hpp) with no output directory. Private to jobs/src/sweep.
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "lrchain/config/strict_toml.hpp"
#include "lrchain/jobs/sweep/job.hpp"
#include "lrchain/jobs/model_source.hpp"
#include "lrchain/sim/run_control.hpp"

namespace lrchain::jobs::sweep {

// The values of a model-file base's [parameters] (NAME, value), in the file's order.
std::vector<std::pair<std::string, double>> model_parameter_values(const lrchain::config::CheckedTable& root);

// The Model of one point of a study base (wave, bright breathers): a model file's with its
// [parameters], or the shipped resonant chain with [model]'s rho, kappa, delta0 and alpha.
struct PointModel {
  std::shared_ptr<const ModelSource> chain;  // the resonant chain's source (no model file)
  std::optional<Model> model;
  const lrchain_lattice_kernels* kernels = nullptr;
};
// `root`: the base checked against its schema; `source`: a model-file base's model, else null.
PointModel point_model(const lrchain::config::CheckedTable& root, const ModelSource* source);

// The base's model loaded once through the one model loader (jobs::ModelSource; `compiler` null:
// shipped model files only), its lattice kernels too (every job but "regime intervals"), after the
// base passed its schema: a missing or bad model file is a ConfigError at the line of `model`, an
// unknown name in [parameters] one at its line.
std::shared_ptr<const ModelSource> load_base_model(const std::string& kind, const lrchain::config::Document& base,
                                                   std::shared_ptr<const ModelCompiler> compiler);

// The summary scalars of a model job ("bright" or "ring"), named as in its JSON summary.
std::vector<std::string> model_job_scalar_names(const std::string& kind);
// The parameters a point may override: "bright.theta", ... (number and integer keys of the job's
// table) and "parameters.NAME" for every parameter of the model.
std::vector<std::string> model_job_parameters(const std::string& kind, const ModelDefinition& model);
// The schema of the base config of a model-file base of `kind` (for renamed keys and axes).
const lrchain::config::TableSchema& model_job_schema(const std::string& kind);

// Runs one point from its (overridden) base config: the point's Model from `source`'s definition and
// the config's [parameters], the job's checks, the run. InputError for a value the checks refuse; a
// ring whose plane wave broke up is status `numerical_failure` with the run's reason (its scalars
// kept); `control.stop` set ends the run with status `missing`.
JobResult run_model_job(const std::string& kind, const ModelSource& source, const lrchain::config::Document& doc,
                        const sim::RunControl& control);

}  // namespace lrchain::jobs::sweep
