// One point of a sweep run in-process (sweep/job.hpp): the base config with overrides, read through
// the same strict config layer as `lrchain simulate --config`, run, reduced to summary scalars.
#include "lrchain/jobs/sweep/job.hpp"

#include <chrono>
#include <cmath>
#include <functional>
#include <limits>
#include <sstream>

#include <fmt/format.h>

#include "lrchain/errors.hpp"
#include "lrchain/jobs/experiment_config.hpp"
#include "lrchain/jobs/model_experiment_config.hpp"
#include "lrchain/jobs/more_experiment_config.hpp"
#include "lrchain/jobs/sweep/study_jobs.hpp"
#include "model_jobs.hpp"
#include "scalar_extractors.hpp"

namespace lrchain::jobs::sweep {

using namespace lrchain::sim;  // the numerics this job layer runs

namespace {

constexpr double none = std::numeric_limits<double>::quiet_NaN();

// The scalars of a bright run (resonant_chain_bright_run.hpp), in file order.
const Extractors<BrightRunSummary>& bright_scalars() {
  static const Extractors<BrightRunSummary> e{
      {"max_Ex", [](const auto& s) { return s.max_Ex; }},
      {"max_Ey", [](const auto& s) { return s.max_Ey; }},
      {"max_Ex_window", [](const auto& s) { return s.max_Ex_window; }},
      {"max_Ey_window", [](const auto& s) { return s.max_Ey_window; }},
      {"final_Ex", [](const auto& s) { return s.final_Ex; }},
      {"final_Ey", [](const auto& s) { return s.final_Ey; }},
      {"max_energy_drift", [](const auto& s) { return s.max_energy_drift; }},
      {"centre_speed", [](const auto& s) { return s.centre_speed; }},
      {"centre_start", [](const auto& s) { return s.centre_start; }},
      {"centre_end", [](const auto& s) { return s.centre_end; }},
      {"omega_b", [](const auto& s) { return s.omega_b; }},
      {"period", [](const auto& s) { return s.period; }},
      {"group_velocity", [](const auto& s) { return s.group_velocity; }},
      {"h_tilde", [](const auto& s) { return s.h_tilde; }},
      {"inverse_width", [](const auto& s) { return s.inverse_width; }},
      {"t_end", [](const auto& s) { return s.t_end; }},
      {"blew_up", [](const auto& s) { return s.blew_up ? 1.0 : 0.0; }},
      {"steps", [](const auto& s) { return double(s.stats.steps); }},
      {"rhs_evaluations", [](const auto& s) { return double(s.stats.rhs_evaluations); }}};
  return e;
}

// The scalars of a driven chain (drive_run.hpp).
const Extractors<DriveRunSummary>& drive_scalars() {
  static const Extractors<DriveRunSummary> e{
      {"theta", [](const auto& s) { return s.theta; }},
      {"group_velocity", [](const auto& s) { return s.group_velocity; }},
      {"front_speed", [](const auto& s) { return s.front_samples >= 2 ? s.front_speed : none; }},
      {"front_samples", [](const auto& s) { return double(s.front_samples); }},
      {"final_participation", [](const auto& s) { return s.final_participation; }},
      {"max_participation", [](const auto& s) { return s.max_participation; }},
      {"final_peaks", [](const auto& s) { return double(s.final_peaks); }},
      {"final_energy", [](const auto& s) { return s.final_energy; }},
      {"max_energy", [](const auto& s) { return s.max_energy; }},
      {"t_end", [](const auto& s) { return s.t_end; }},
      {"blew_up", [](const auto& s) { return s.blew_up ? 1.0 : 0.0; }},
      {"steps", [](const auto& s) { return double(s.stats.steps); }}};
  return e;
}

// The scalars of a modulated wave (modulated_run.hpp); instability_time is NaN when there is none.
const Extractors<ModulatedRunSummary>& modulated_scalars() {
  static const Extractors<ModulatedRunSummary> e{
      {"theta0", [](const auto& s) { return s.theta0; }},
      {"omega", [](const auto& s) { return s.omega; }},
      {"group_velocity", [](const auto& s) { return s.group_velocity; }},
      {"initial_contrast", [](const auto& s) { return s.initial_contrast; }},
      {"instability_time", [](const auto& s) { return s.instability_time ? *s.instability_time : none; }},
      {"dark_speed", [](const auto& s) { return s.dark_samples >= 2 ? s.dark_speed : none; }},
      {"dark_samples", [](const auto& s) { return double(s.dark_samples); }},
      {"max_energy_drift", [](const auto& s) { return s.max_energy_drift; }},
      {"t_end", [](const auto& s) { return s.t_end; }},
      {"blew_up", [](const auto& s) { return s.blew_up ? 1.0 : 0.0; }},
      {"steps", [](const auto& s) { return double(s.stats.steps); }}};
  return e;
}

// Fills the result from a finished run's summary: scalars, and the status from interrupt/blow-up.
template <class Summary>
void reduce(const Summary& s, const Extractors<Summary>& e, JobResult& r) {
  append_scalars(s, e, r.scalars);
  if (s.interrupted) {
    r.status = PointStatus::missing;
    r.reason = "interrupted";
  } else if (s.blew_up) {
    r.status = PointStatus::blew_up;
    r.reason = s.blow_up ? s.blow_up->message() : "the integration blew up";
  } else {
    r.status = PointStatus::ok;
  }
}

// The base document with each override written as a number string (shortest text that reads
// back as the same double), re-read through the config layer so that every check applies.
config::Document with_overrides(const config::Document& base, const Overrides& overrides) {
  toml::table root = base.root();
  for (const auto& [parameter, value] : overrides) {
    const auto dot = parameter.find('.');
    const std::string table = parameter.substr(0, dot), key = parameter.substr(dot + 1);
    if (!root[table].is_table()) root.insert_or_assign(table, toml::table{});
    root[table].as_table()->insert_or_assign(key, fmt::format("{}", value));
  }
  std::ostringstream text;
  text << root;
  return config::Document::from_text(text.str(), base.source());
}

}  // namespace

const char* to_string(PointStatus s) {
  switch (s) {
    case PointStatus::missing: return "missing";
    case PointStatus::ok: return "ok";
    case PointStatus::blew_up: return "blew_up";
    case PointStatus::numerical_failure: return "numerical_failure";
    case PointStatus::invalid: return "invalid";
  }
  return "missing";
}

std::string status_legend() { return "0 missing, 1 ok, 2 blew_up, 3 numerical_failure, 4 invalid"; }

std::vector<std::string> job_kinds() {
  std::vector<std::string> k = experiment_kinds();
  k.push_back("ring");  // model files only
  k.insert(k.end(), study_kinds().begin(), study_kinds().end());
  return k;
}

std::string job_kind(const config::Document& doc) {
  static const config::TableSchema first_look{
      "", {config::choice("experiment", job_kinds(), "", "").require()}, config::anything("")};
  std::string kind;
  config::check(doc, first_look).read("experiment", kind);
  return kind;
}

std::string Job::rows_legend() const {
  return is_study_kind(kind_) ? study_rows_legend(kind_, model_ ? model_->definition().get() : nullptr) : std::string();
}

Job::Job(config::Document base, std::shared_ptr<const ModelCompiler> compiler)
    : base_(std::move(base)), kind_(job_kind(base_)) {
  if (is_model_experiment(base_) || kind_ == "ring") {
    model_ = load_base_model(kind_, base_, std::move(compiler));
    if (is_study_kind(kind_)) {
      check_study_config(kind_, base_, model_.get());
      scalar_names_ = study_scalar_names(kind_, model_->definition().get());
      row_names_ = study_row_names(kind_);
    } else {
      scalar_names_ = model_job_scalar_names(kind_);
    }
  } else if (is_study_kind(kind_)) {
    check_study_config(kind_, base_);
    scalar_names_ = study_scalar_names(kind_);
    row_names_ = study_row_names(kind_);
  } else if (kind_ == "bright") {
    load_experiment_config(base_);
    scalar_names_ = names_of(bright_scalars());
  } else if (kind_ == "drive") {
    load_drive_config(base_);
    scalar_names_ = names_of(drive_scalars());
  } else {
    load_modulated_config(base_);
    scalar_names_ = names_of(modulated_scalars());
  }
}

std::vector<std::string> Job::parameters() const {
  if (model_) return model_job_parameters(kind_, *model_->definition());
  std::vector<std::string> p;
  const auto& schema = is_study_kind(kind_) ? study_schema(kind_) : experiment_schema(kind_);
  for (const auto& table : schema.keys) {
    if (table.type != config::ValueType::table) continue;
    for (const auto& key : table.table->keys)
      if (key.type == config::ValueType::number || key.type == config::ValueType::integer)
        p.push_back(table.name + "." + key.name);
  }
  return p;
}

bool Job::has_parameter(const std::string& parameter) const {
  for (const auto& p : parameters())
    if (p == parameter) return true;
  return false;
}

std::optional<config::RenamedKey> Job::renamed_parameter(const std::string& parameter) const {
  const auto& schema = model_ ? model_job_schema(kind_) : is_study_kind(kind_) ? study_schema(kind_) : experiment_schema(kind_);
  for (const auto& table : schema.keys) {
    if (table.type != config::ValueType::table) continue;
    for (const auto& r : table.table->renamed)
      if (parameter == table.name + "." + r.old_name)
        return config::RenamedKey{parameter, table.name + "." + r.new_name, r.note};
  }
  return std::nullopt;
}

JobResult Job::run(const Overrides& overrides, const RunControl& control) const {
  JobWorkspace workspace;
  return run(overrides, control, workspace);
}

JobResult Job::run(const Overrides& overrides, const RunControl& control, JobWorkspace& workspace) const {
  const auto start = std::chrono::steady_clock::now();
  JobResult r;
  try {
    const config::Document doc = with_overrides(base_, overrides);
    if (is_study_kind(kind_))
      r = run_study(kind_, doc, control, model_.get());
    else if (model_)
      r = run_model_job(kind_, *model_, doc, control);
    else if (kind_ == "bright")
      reduce(run_resonant_chain_bright(load_experiment_config(doc).bright, workspace.bright, control), bright_scalars(), r);
    else if (kind_ == "drive")
      reduce(run_drive(load_drive_config(doc).run, control).summary, drive_scalars(), r);
    else
      reduce(run_modulated(load_modulated_config(doc).run, control).summary, modulated_scalars(), r);
  } catch (const InputError& e) {
    r = JobResult{PointStatus::invalid, e.what(), {}, 0, {}};
  } catch (const NumericalFailure& e) {
    r = JobResult{PointStatus::numerical_failure, e.what(), {}, 0, {}};
  }
  if (r.scalars.empty()) r.scalars.assign(scalar_names_.size(), none);
  r.wall_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return r;
}

}  // namespace lrchain::jobs::sweep
