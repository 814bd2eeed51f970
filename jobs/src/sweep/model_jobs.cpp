// The sweep jobs of model-file bases, "bright" and "ring" (sweep/model_jobs.hpp): the model loaded
// once, each point's Model from its [parameters], the run through the simulate job function.
#include "model_jobs.hpp"

#include <algorithm>
#include <functional>
#include <limits>
#include <utility>

#include <fmt/format.h>

#include "lrchain/errors.hpp"
#include "lrchain/jobs/model_experiment_config.hpp"
#include "lrchain/jobs/simulate/model_simulate_job.hpp"
#include "lrchain/jobs/sweep/study_jobs.hpp"
#include "scalar_extractors.hpp"
// Last: it opens namespace lrchain::jobs::config, which would hide lrchain::config in the headers above.
#include "../located_validation.hpp"

namespace lrchain::jobs::sweep {

namespace {

constexpr double missing_value = std::numeric_limits<double>::quiet_NaN();

double value_or_nan(const std::optional<double>& v) { return v ? *v : missing_value; }

// The scalars of a model bright run, named as in its JSON summary (model_bright_outputs.cpp).
const Extractors<sim::ModelBrightResult>& model_bright_scalars() {
  static const Extractors<sim::ModelBrightResult> e{
      {"omega", [](const auto& r) { return r.omega; }},
      {"omega_b", [](const auto& r) { return r.omega_b; }},
      {"T_b", [](const auto& r) { return r.period; }},
      {"group_velocity", [](const auto& r) { return r.group_velocity; }},
      {"curvature", [](const auto& r) { return r.curvature; }},
      {"h_tilde", [](const auto& r) { return r.h_tilde; }},
      {"lambda", [](const auto& r) { return r.mean_flow ? r.lambda : missing_value; }},
      {"M1", [](const auto& r) { return r.M1; }},
      {"M2", [](const auto& r) { return r.M2; }},
      {"inverse_width", [](const auto& r) { return r.inverse_width; }},
      {"max_E_x", [](const auto& r) { return r.max_error.at(0); }},
      {"final_E_x", [](const auto& r) { return r.final_error.at(0); }},
      {"energy0", [](const auto& r) { return r.energy0; }},
      {"max_relative_energy_drift", [](const auto& r) { return r.ansatz_ends ? missing_value : r.max_energy_drift; }},
      {"centre_speed", [](const auto& r) { return value_or_nan(r.centre_speed); }},
      {"centre_speed_vs_c",
       [](const auto& r) { return r.centre_speed && r.group_velocity != 0 ? *r.centre_speed / r.group_velocity : missing_value; }},
      {"t_end", [](const auto& r) { return r.stats.t_reached; }},
      {"steps", [](const auto& r) { return double(r.stats.steps); }},
      {"rhs_evaluations", [](const auto& r) { return double(r.stats.rhs_evaluations); }}};
  return e;
}

// The largest relative disagreement of the measured and predicted frequency shifts (NaN: none).
double max_relative_disagreement(const sim::RingRunResult& r) {
  double most = missing_value;
  for (const auto& a : r.amplitudes)
    if (a.relative_disagreement && !(*a.relative_disagreement <= most)) most = *a.relative_disagreement;
  return most;
}

// The scalars of a ring run (ring_outputs.cpp): the prediction, the first amplitude's frequencies,
// the worst disagreement over the amplitudes, the packet.
const Extractors<sim::RingRunResult>& ring_run_scalars() {
  static const Extractors<sim::RingRunResult> e{
      {"omega", [](const auto& r) { return r.omega; }},
      {"h", [](const auto& r) { return r.h; }},
      {"group_velocity", [](const auto& r) { return r.group_velocity; }},
      {"sites", [](const auto& r) { return double(r.sites); }},
      {"mode_number", [](const auto& r) { return double(r.mode_number); }},
      {"measured_frequency",
       [](const auto& r) { return r.amplitudes.at(0).broke_up_at ? missing_value : r.amplitudes.at(0).measured_frequency; }},
      {"predicted_frequency", [](const auto& r) { return r.amplitudes.at(0).predicted_frequency; }},
      {"relative_disagreement", [](const auto& r) { return value_or_nan(r.amplitudes.at(0).relative_disagreement); }},
      {"max_relative_disagreement", [](const auto& r) { return max_relative_disagreement(r); }},
      {"packet_speed", [](const auto& r) { return r.packet_speed; }},
      {"packet_relative_disagreement", [](const auto& r) { return value_or_nan(r.packet_relative_disagreement); }}};
  return e;
}

template <class Result>
void reduce_model_run(const Result& r, const Extractors<Result>& e, JobResult& out) {
  append_scalars(r, e, out.scalars);
  out.status = PointStatus::ok;
}

// A ConfigError at the top-level key `key` of the base config.
lrchain::config::ConfigError base_key_error(const lrchain::config::CheckedTable& root, const std::string& key, const std::string& what) {
  const long line = root.line(key) ? root.line(key) : root.line();
  return lrchain::config::ConfigError(fmt::format("invalid value for '{}' in the top level at {}:{}: {}", key, root.source(), line, what),
                             root.source(), line, root.path(), key);
}

}  // namespace

std::vector<std::pair<std::string, double>> model_parameter_values(const lrchain::config::CheckedTable& root) {
  std::vector<std::pair<std::string, double>> values;
  if (const auto p = root.table("parameters"))
    for (const auto& key : p->keys()) values.emplace_back(key, *p->number(key));
  return values;
}

PointModel point_model(const lrchain::config::CheckedTable& root, const ModelSource* source) {
  PointModel p;
  if (source) {
    p.model.emplace(source->model(model_parameter_values(root)));
    p.kernels = source->lattice().kernels.get();
    return p;
  }
  p.chain = std::make_shared<const ModelSource>(ModelSource::shipped("resonant_chain", "[model]"));
  std::vector<std::pair<std::string, double>> values;
  if (auto m = root.table("model"))
    for (const char* name : {"alpha", "delta0", "kappa", "rho"})
      if (double v = 0; m->read(name, v)) values.emplace_back(name, v);
  p.model.emplace(p.chain->model(values));
  p.kernels = p.chain->lattice().kernels.get();
  return p;
}

std::shared_ptr<const ModelSource> load_base_model(const std::string& kind, const lrchain::config::Document& base,
                                                   std::shared_ptr<const ModelCompiler> compiler) {
  if (!is_study_kind(kind)) load_model_experiment_config(base);  // the schema and the job's own checks first
  const lrchain::config::CheckedTable root = lrchain::config::check(base, model_job_schema(kind));
  std::string file;
  root.read("model", file);
  const std::vector<std::pair<std::string, double>> values = model_parameter_values(root);
  std::shared_ptr<const ModelSource> source;
  try {
    // As `lrchain simulate --config` loads it: for a lattice run (every job but "regime intervals",
    // which evaluates coefficients only) a user's file whose lattice code can be neither found nor
    // compiled is refused before its evaluators are compiled, and the kernels are loaded now, once,
    // so that the points' threads only read them.
    const bool lattice_run = kind != "regime intervals";
    source = std::make_shared<const ModelSource>(file, "model", std::move(compiler), lattice_run);
    if (lattice_run) source->lattice();
  } catch (const InputError& e) {
    throw base_key_error(root, "model", e.what());
  }
  // The base's own parameter values: an unknown name or a value outside its range at its line.
  if (const auto parameters = root.table("parameters"))
    jobs::config::validate_located(*parameters, [&] { source->model(values); });
  return source;
}

std::vector<std::string> model_job_scalar_names(const std::string& kind) {
  return kind == "ring" ? names_of(ring_run_scalars()) : names_of(model_bright_scalars());
}

const lrchain::config::TableSchema& model_job_schema(const std::string& kind) {
  return is_study_kind(kind) ? model_study_schema(kind) : model_experiment_schema(kind);
}

std::vector<std::string> model_job_parameters(const std::string& kind, const ModelDefinition& model) {
  std::vector<std::string> p;
  for (const auto& table : model_job_schema(kind).keys) {
    if (table.type != lrchain::config::ValueType::table || table.name == "parameters") continue;
    for (const auto& key : table.table->keys)
      if (key.type == lrchain::config::ValueType::number || key.type == lrchain::config::ValueType::integer)
        p.push_back(table.name + "." + key.name);
  }
  for (const auto& parameter : model.parameters) p.push_back("parameters." + parameter.name);
  return p;
}

JobResult run_model_job(const std::string& kind, const ModelSource& source, const lrchain::config::Document& doc,
                        const sim::RunControl& control) {
  ModelExperimentConfig mc = load_model_experiment_config(doc);
  const Model model = source.model(mc.parameters);
  const lrchain_lattice_kernels& kernels = *source.lattice().kernels;  // loaded by load_base_model
  const RunOutput no_files{"", false, "csv"};
  JobResult r;
  try {
    if (kind == "ring") {
      prepare(model, mc.ring, mc.branch);
      const sim::RingRunResult ring = simulate_ring(model, kernels, mc.ring, {}, no_files, control.stop).result;
      reduce_model_run(ring, ring_run_scalars(), r);
      if (ring.failure) {  // a plane wave broke up: `lrchain simulate` exits 3 with this reason
        r.status = PointStatus::numerical_failure;
        r.reason = *ring.failure;
      }
    } else {
      prepare(model, mc.bright, mc.branch);
      reduce_model_run(simulate_model_bright(model, kernels, mc.bright, {}, no_files, control.stop).result, model_bright_scalars(), r);
    }
  } catch (const Interrupted&) {
    r = JobResult{PointStatus::missing, "interrupted", {}, 0, {}};
  }
  return r;
}

}  // namespace lrchain::jobs::sweep
