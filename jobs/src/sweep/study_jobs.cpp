// The "dark continue", "regime intervals", "wave ..." and "bright ..." sweep jobs (sweep/study_jobs.hpp): their base
// configs' schemas, and one point run in-process and reduced to scalars and rows.
#include "lrchain/jobs/sweep/study_jobs.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <map>
#include <optional>
#include <stdexcept>

#include <fmt/format.h>

#include "../toml_reading.hpp"
#include "lrchain/ansatz/dark_breather.hpp"
#include "lrchain/dispersion.hpp"
#include "lrchain/config/option_caps.hpp"
#include "lrchain/errors.hpp"
#include "lrchain/jobs/dark_job.hpp"
#include "lrchain/jobs/model_experiment_config.hpp"
#include "lrchain/jobs/regime_job.hpp"
#include "lrchain/sim/dark/dark_ansatz.hpp"
#include "bright_study.hpp"
#include "model_jobs.hpp"
#include "wave_study.hpp"

namespace lrchain::jobs::sweep {

using namespace lrchain::sim;  // the numerics this job layer runs

namespace {

using namespace lrchain::config;
constexpr double no_scalar = std::numeric_limits<double>::quiet_NaN();

// [dark]: the options of `lrchain dark continue`.
std::shared_ptr<const TableSchema> dark_table() {
  return std::make_shared<const TableSchema>(TableSchema{
      "a dark-breather branch continued in omega_b (Secs. 5.3-5.4), as `lrchain dark continue`",
      {number("omega_b", NumberRange::positive(), "none", "start frequency omega_b, below the theta = pi band edge"),
       number("edge_offset", NumberRange::positive(), "none",
              "start at omega_b = omega(pi) - edge_offset instead (for sweeps over the model)"),
       choice("branch", {"optical", "acoustic"}, "optical", "branch whose theta = pi band edge the breather bifurcates from"),
       choice("center", {"bond", "site"}, "bond", "family: bond (n0 = 1/2) or site (n0 = 0)"),
       integer("sites", 9, 1'000'001, "101", "odd number of lattice sites per field (periodic ends)"),
       choice("mode", {"reversible", "full"}, "reversible", "shooting over a half/quarter period or the whole period"),
       integer("points", 1, 1'000'000, "100", "maximum number of branch points, the first included"),
       number("ds", NumberRange::between(0, 1, true, false), "0.1", "initial pseudo-arclength step (adapted in [1e-5, 1])"),
       number("omega_min", NumberRange::non_negative(), "0", "stop when omega_b falls below this"),
       number("omega_max", NumberRange::non_negative(), "0 (the band edge)", "stop when omega_b rises above this")},
      std::nullopt,
      {{"edge", "branch"}}});
}

// [regime]: the options of `lrchain regime intervals` (both branches are run).
std::shared_ptr<const TableSchema> regime_table() {
  return std::make_shared<const TableSchema>(TableSchema{
      "the focusing theta-intervals of both branches (Sec. 3.3), as `lrchain regime intervals`",
      {integer("samples", intervals_samples.least, intervals_samples.most,
               std::to_string(RegimeIntervalsConfig{}.samples), "theta samples used to bracket the zeros")},
      std::nullopt});
}

TableSchema study_top(const std::string& kind, const std::string& table_name, std::shared_ptr<const TableSchema> t,
                      bool table_required) {
  return TableSchema{"a \"" + kind + "\" sweep base",
                     {choice("experiment", {kind}, "", "which job this file describes").require(),
                      string("name", "the file name without .toml", "a label"),
                      table("model", jobs::config::model_schema(Params{})),
                      table_required ? table(table_name, t).require() : table(table_name, t)},
                     std::nullopt};
}

using StudySchemas = std::map<std::string, TableSchema, std::less<>>;

// The base schema of a study kind; InvalidParameter("experiment") for any other kind.
const TableSchema& schema_of(const StudySchemas& schemas, std::string_view kind) {
  const auto it = schemas.find(kind);
  if (it == schemas.end()) throw InvalidParameter("experiment", "must be one of the study jobs (study_kinds())");
  return it->second;
}

// A model-file base of a study job: `model = "models/x.toml"` and its [parameters] (as a model-file
// simulate config has them, model_experiment_config.hpp) in place of the resonant chain's [model].
TableSchema model_study_top(const std::string& kind, const std::string& table_name, std::shared_ptr<const TableSchema> t,
                            bool table_required) {
  const TableSchema& simulate = model_experiment_schema("bright");
  return TableSchema{"a \"" + kind + "\" sweep base of a model file",
                     {choice("experiment", {kind}, "", "which job this file describes").require(),
                      string("name", "the file name without .toml", "a label"), *simulate.find("model"),
                      *simulate.find("parameters"), table_required ? table(table_name, t).require() : table(table_name, t)},
                     std::nullopt};
}

Params read_model(const CheckedTable& root) {
  Params p;
  if (auto m = root.table("model")) {
    m->read("rho", p.rho);
    m->read("kappa", p.kappa);
    m->read("delta0", p.delta0);
    m->read("alpha", p.alpha);
  }
  validate(p);
  return p;
}

// ---- dark continue ---------------------------------------------------------------------------

// The name a refused [dark] key goes by in a point's reason.
std::string dark_key(const Document& doc, std::string_view key) { return fmt::format("[dark] {} in {}", key, doc.source()); }

// The options of [dark] that the chain's and a model file's bases share, read into `c`.
void read_dark_options(const CheckedTable& d, jobs::dark::DarkConfig& c) {
  d.read("branch", c.branch);
  d.read("center", c.center);
  d.read("mode", c.mode);
  if (Index sites = 0; d.read("sites", sites)) c.sites = sites;
  d.read("points", c.points);
  d.read("ds", c.ds);
  d.read("omega_min", c.omega_min);
  d.read("omega_max", c.omega_max);
}

// [dark] of a model-file base: the chain's options, with the branch one of the model's (none: its
// first defocusing edge) and edge_offset measured on the breather's side of that edge.
std::shared_ptr<const TableSchema> model_dark_table() {
  TableSchema t = *dark_table();
  t.meaning = "a dark-breather branch of the model continued in omega_b, as `lrchain dark continue --model`";
  for (auto& key : t.keys) {
    if (key.name == "branch")
      key = string("branch", "none", "branch of the model whose band edge the breather bifurcates from (none: the first defocusing edge)");
    if (key.name == "edge_offset")
      key.meaning = "start at omega_b = omega(edge) + sign(h_tilde) edge_offset instead (the breather's side of the edge)";
  }
  return std::make_shared<const TableSchema>(std::move(t));
}

// Reads a model-file base's [dark] into the dark job's config (branch step) on `model` (the point's
// Model) and `source`'s lattice kernels, with the dark job's checks (InvalidParameter naming the key).
jobs::dark::DarkConfig read_model_dark(const Document& doc, const Model& model, const ModelSource& source) {
  const CheckedTable root = check(doc, model_study_schema("dark continue"));
  jobs::dark::DarkConfig c;
  c.step = jobs::dark::DarkStep::branch;
  c.model = &model;
  c.kernels = source.lattice().kernels.get();
  const CheckedTable d = *root.table("dark");
  const std::optional<double> start = d.number("omega_b"), edge_offset = d.number("edge_offset");
  read_dark_options(d, c);
  if (start.has_value() == edge_offset.has_value())
    throw InvalidParameter(dark_key(doc, "omega_b"), "give exactly one of 'omega_b' and 'edge_offset'");
  try {
    if (edge_offset) {  // (omega_b - omega) h_tilde > 0 at the edge the dark job starts from
      const std::optional<Index> given = c.branch.empty() ? std::nullopt : std::optional(model.branch(c.branch));
      const sim::dark::DefocusingEdge edge = sim::dark::defocusing_edge(model, given);
      const NlsCoefficients k = coefficients(model, edge.branch, edge.theta);
      c.omega_b = k.omega + (k.h_tilde > 0 ? *edge_offset : -*edge_offset);
    } else {
      c.omega_b = *start;
    }
    jobs::dark::validate(c);
  } catch (const InvalidParameter& e) {
    const std::string what = e.what(), prefix = "invalid " + e.parameter() + ": ";
    const std::string parameter = e.parameter() == "omega_b" && edge_offset ? "edge_offset" : e.parameter();
    throw InvalidParameter(dark_key(doc, parameter), what.rfind(prefix, 0) == 0 ? what.substr(prefix.size()) : what);
  }
  return c;
}

// Reads [model] and [dark] into the dark job's config (branch step) with the checks of `lrchain dark
// continue` (InvalidParameter naming the key in the file); also the ansatz at the start frequency.
std::pair<jobs::dark::DarkConfig, DarkBreatherAnsatz> read_dark(const Document& doc) {
  const CheckedTable root = check(doc, study_schema("dark continue"));
  jobs::dark::DarkConfig c;
  c.step = jobs::dark::DarkStep::branch;
  c.params = read_model(root);
  c.branch = "optical";
  const CheckedTable d = *root.table("dark");
  const std::optional<double> start = d.number("omega_b"), edge_offset = d.number("edge_offset");
  read_dark_options(d, c);
  const auto key = [&](const char* k) { return dark_key(doc, k); };
  if (start.has_value() == edge_offset.has_value())
    throw InvalidParameter(key("omega_b"), "give exactly one of 'omega_b' and 'edge_offset'");
  if (c.sites && *c.sites % 2 == 0)
    throw InvalidParameter(key("sites"), "must be an odd integer >= 9 (a staggered dark breather fits periodic ends only on an odd number of sites)");
  const Branch edge = parse_branch(c.branch);
  const double edge_omega = dispersion_omega(c.params, edge, std::acos(-1.0));
  c.omega_b = start ? *start : edge_omega - *edge_offset;
  const char* start_key = start ? "omega_b" : "edge_offset";
  if (!(c.omega_b > 0)) throw InvalidParameter(key(start_key), fmt::format("must start below the band edge omega(pi) = {:g}", edge_omega));
  DarkBreatherAnsatz ansatz;
  try {
    ansatz = make_dark_breather_ansatz(c.params, edge, c.omega_b);  // checks omega_b against the edge
  } catch (const InvalidParameter& e) {
    const std::string what = e.what(), prefix = "invalid " + e.parameter() + ": ";
    throw InvalidParameter(key(start_key), what.rfind(prefix, 0) == 0 ? what.substr(prefix.size()) : what);
  }
  if (!(c.omega_min < c.omega_b))
    throw InvalidParameter(key("omega_min"), fmt::format("must be below the start omega_b = {:g}", c.omega_b));
  if (c.omega_max > 0 && !(c.omega_max > c.omega_b))
    throw InvalidParameter(key("omega_max"), fmt::format("must be 0 (the band edge) or above the start omega_b = {:g}", c.omega_b));
  return {c, ansatz};
}

const std::vector<std::string>& dark_scalar_names() {
  static const std::vector<std::string> n{
      "start_omega_b", "omega_edge", "newton_iterations", "branch_points", "turning_points", "first_turning_point",
      "omega_b_low", "omega_b_high", "stable_points", "real_unstable_points", "period_doubling_points",
      "oscillatory_unstable_points", "stable_windows", "unstable_windows", "stable_omega_extent",
      "unstable_omega_extent", "max_floquet_modulus", "max_real_multiplier", "max_oscillatory_multiplier", "max_E_b"};
  return n;
}
const std::vector<std::string>& dark_row_names() {
  static const std::vector<std::string> n{"omega_b",     "norm_squared", "K_x",      "E_b",
                                          "stability",   "max_modulus",  "max_real", "max_period_doubling",
                                          "max_oscillatory", "part",     "iterations"};
  return n;
}

// Stability code of a branch point: 0 stable, + 1 real, + 2 period doubling, + 4 oscillatory.
int stability_code(const sim::dark::FloquetResult& f) {
  return (f.real_instability ? 1 : 0) + (f.period_doubling ? 2 : 0) + (f.oscillatory ? 4 : 0);
}

// The branch reduced to the scalars of dark_scalar_names() and one row per point.
void reduce_branch(const sim::dark::BranchResult& br, double omega_b, double omega_edge, int newton_iterations, JobResult& r) {
  const auto& pts = br.points;
  double low = no_scalar, high = no_scalar, max_mod = 0, max_real = 1, max_osc = 1, max_E = 0, stable_extent = 0, unstable_extent = 0;
  int stable = 0, real = 0, doubling = 0, oscillatory = 0, stable_windows = 0, unstable_windows = 0, part = 0;
  double last_tangent = -1;
  for (std::size_t i = 0; i < pts.size(); ++i) {
    const auto& b = pts[i];
    const bool ok = stability_code(b.floquet) == 0;
    low = i == 0 ? b.omega_b : std::min(low, b.omega_b);
    high = i == 0 ? b.omega_b : std::max(high, b.omega_b);
    stable += ok;
    real += b.floquet.real_instability;
    doubling += b.floquet.period_doubling;
    oscillatory += b.floquet.oscillatory;
    max_mod = std::max(max_mod, b.floquet.max_modulus);
    max_real = std::max(max_real, b.floquet.max_real);
    max_osc = std::max(max_osc, b.floquet.max_oscillatory);
    max_E = std::max(max_E, b.measures.E_b);
    const bool new_window = i == 0 || (stability_code(pts[i - 1].floquet) == 0) != ok;
    if (new_window) (ok ? stable_windows : unstable_windows) += 1;
    else (ok ? stable_extent : unstable_extent) += std::abs(b.omega_b - pts[i - 1].omega_b);
    if ((b.tangent_omega > 0) != (last_tangent > 0)) ++part;  // as the parts of `lrchain dark continue`
    last_tangent = b.tangent_omega;
    r.rows.insert(r.rows.end(), {b.omega_b, b.measures.norm_squared, b.measures.K_x, b.measures.E_b,
                                 double(stability_code(b.floquet)), b.floquet.max_modulus, b.floquet.max_real,
                                 b.floquet.max_period_doubling, b.floquet.max_oscillatory, double(part),
                                 double(b.iterations)});
  }
  r.scalars = {omega_b, omega_edge, double(newton_iterations), double(pts.size()), double(br.turning_points.size()),
               br.turning_points.empty() ? no_scalar : br.turning_points.front(), low, high, double(stable), double(real),
               double(doubling), double(oscillatory), double(stable_windows), double(unstable_windows), stable_extent,
               unstable_extent, max_mod, max_real, max_osc, max_E};
}

// Seed, Newton, continuation with Floquet at every point: the dark job's branch step (dark_job.hpp).
JobResult run_dark(const Document& doc, const RunControl& control, const ModelSource* source) {
  std::optional<Model> model;  // a model-file base: the point's model (the job's config points at it)
  jobs::dark::DarkConfig c;
  if (source) {
    model.emplace(source->model(model_parameter_values(check(doc, model_study_schema("dark continue")))));
    c = read_model_dark(doc, *model, *source);
  } else {
    c = read_dark(doc).first;
  }
  jobs::dark::DarkRunHooks hooks;
  hooks.stop = control.stop;
  const jobs::dark::DarkResult d = jobs::dark::run(c, hooks);
  JobResult r;
  if (!d.newton.converged) {
    r.status = PointStatus::numerical_failure;
    r.reason = fmt::format("Newton found no breather at omega_b = {}: {}", c.omega_b, d.newton.failure);
    return r;
  }
  if (d.branch.interrupted) {
    r.status = PointStatus::missing;
    r.reason = "interrupted";
    return r;
  }
  reduce_branch(d.branch, c.omega_b, d.edge.omega, int(d.newton.history.size()), r);
  if (const auto failure = jobs::dark::failure(d)) {  // the corrector failed at once
    r.status = PointStatus::numerical_failure;
    r.reason = *failure;
  } else {
    r.status = PointStatus::ok;
  }
  return r;
}

// ---- regime intervals ------------------------------------------------------------------------

// The branches a regime point runs: both of the resonant chain, or every branch of a model file.
std::vector<std::string> regime_branches(const ModelDefinition* model) {
  if (model) return model->branch_names;
  return {std::string(to_string(Branch::optical)), std::string(to_string(Branch::acoustic))};
}

std::vector<std::string> regime_scalar_names(const ModelDefinition* model) {
  std::vector<std::string> n;
  for (const auto& b : regime_branches(model))
    for (const char* s : {"intervals", "focusing_length", "first_lo", "first_hi", "last_lo", "last_hi"})
      n.push_back(fmt::format("{}_{}", b, s));
  return n;
}

// The focusing intervals of every branch: the job of `lrchain regime intervals --branch B` (with
// `--model FILE` for a model-file base, whose point's Model takes the base's [parameters]).
JobResult run_regime(const Document& doc, const ModelSource* source) {
  const CheckedTable root = check(doc, source ? model_study_schema("regime intervals") : study_schema("regime intervals"));
  RegimeLattice lattice;
  if (source)
    lattice.model = std::make_shared<const Model>(source->model(model_parameter_values(root)));
  else
    lattice.params = read_model(root);
  std::int64_t samples = RegimeIntervalsConfig{}.samples;
  if (auto r = root.table("regime")) r->read("samples", samples);
  JobResult r;
  const std::vector<std::string> branches = regime_branches(source ? source->definition().get() : nullptr);
  for (std::size_t b = 0; b < branches.size(); ++b) {
    RegimeIntervalsConfig config;
    config.lattice = lattice;
    config.branch = branches[b];
    config.samples = int(samples);
    const auto s = run(config).structure;
    double length = 0;
    for (const auto& i : s.intervals) {
      length += i.hi - i.lo;
      r.rows.insert(r.rows.end(), {double(b), i.lo, i.hi, i.hi - i.lo, double(int(i.lo_cause)), double(int(i.hi_cause))});
    }
    const bool any = !s.intervals.empty();
    r.scalars.insert(r.scalars.end(), {double(s.intervals.size()), length, any ? s.intervals.front().lo : no_scalar,
                                       any ? s.intervals.front().hi : no_scalar, any ? s.intervals.back().lo : no_scalar,
                                       any ? s.intervals.back().hi : no_scalar});
  }
  r.status = PointStatus::ok;
  return r;
}

}  // namespace

const std::vector<std::string>& study_kinds() {
  static const std::vector<std::string> k{"dark continue", "regime intervals", "wave stability", "wave fate",
                                          "wave standing", "bright floquet", "bright continue"};
  return k;
}

bool is_wave_kind(std::string_view kind) {
  return kind == "wave stability" || kind == "wave fate" || kind == "wave standing";
}

bool is_bright_kind(std::string_view kind) { return kind == "bright floquet" || kind == "bright continue"; }

bool is_study_kind(std::string_view kind) {
  return std::find(study_kinds().begin(), study_kinds().end(), kind) != study_kinds().end();
}

const TableSchema& study_schema(std::string_view kind) {
  static const StudySchemas schemas{{"dark continue", study_top("dark continue", "dark", dark_table(), true)},
                                    {"regime intervals", study_top("regime intervals", "regime", regime_table(), false)},
                                    {"wave stability", study_top("wave stability", "wave", wave_table("wave stability"), true)},
                                    {"wave fate", study_top("wave fate", "wave", wave_table("wave fate"), true)},
                                    {"wave standing", study_top("wave standing", "wave", wave_table("wave standing"), true)},
                                    {"bright floquet", study_top("bright floquet", "bright", bright_table("bright floquet"), true)},
                                    {"bright continue", study_top("bright continue", "bright", bright_table("bright continue"), true)}};
  return schema_of(schemas, kind);
}

const TableSchema& model_study_schema(std::string_view kind) {
  static const StudySchemas schemas{
      {"dark continue", model_study_top("dark continue", "dark", model_dark_table(), true)},
      {"regime intervals", model_study_top("regime intervals", "regime", regime_table(), false)},
      {"wave stability", model_study_top("wave stability", "wave", wave_table("wave stability"), true)},
      {"wave fate", model_study_top("wave fate", "wave", wave_table("wave fate"), true)},
      {"wave standing", model_study_top("wave standing", "wave", wave_table("wave standing"), true)},
      {"bright floquet", model_study_top("bright floquet", "bright", bright_table("bright floquet"), true)},
      {"bright continue", model_study_top("bright continue", "bright", bright_table("bright continue"), true)}};
  return schema_of(schemas, kind);
}

void check_study_config(std::string_view kind, const Document& doc, const ModelSource* model) {
  if (is_wave_kind(kind)) {
    check_wave_base(kind, doc, check(doc, model ? model_study_schema(kind) : study_schema(kind)), model);
  } else if (is_bright_kind(kind)) {
    check_bright_base(kind, doc, check(doc, model ? model_study_schema(kind) : study_schema(kind)), model);
  } else if (model) {
    const Model point = model->model(model_parameter_values(check(doc, model_study_schema(kind))));
    if (kind == "dark continue") read_model_dark(doc, point, *model);
  } else if (kind == "dark continue")
    read_dark(doc);
  else
    read_model(check(doc, study_schema(kind)));
}

std::vector<std::string> study_scalar_names(std::string_view kind, const ModelDefinition* model) {
  if (is_wave_kind(kind)) return wave_scalar_names(kind);
  if (is_bright_kind(kind)) return bright_scalar_names(kind);
  return kind == "dark continue" ? dark_scalar_names() : regime_scalar_names(model);
}

std::vector<std::string> study_row_names(std::string_view kind) {
  if (kind == "dark continue") return dark_row_names();
  if (is_wave_kind(kind)) return wave_row_names(kind);
  if (is_bright_kind(kind)) return bright_row_names(kind);
  return {"branch", "lo", "hi", "length", "lo_cause", "hi_cause"};
}

std::string study_rows_legend(std::string_view kind, const ModelDefinition* model) {
  if (is_wave_kind(kind)) return wave_rows_legend(kind);
  if (is_bright_kind(kind)) return bright_rows_legend(kind);
  if (kind == "dark continue")
    return "one row per branch point in continuation order; stability: 0 stable, +1 real, +2 period doubling, "
           "+4 oscillatory instability; part: 0 before the first turning point, +1 after each; max_real, "
           "max_period_doubling, max_oscillatory: 1 when there is none";
  std::string branches;
  const std::vector<std::string> names = regime_branches(model);
  for (std::size_t b = 0; b < names.size(); ++b) branches += fmt::format("{}{} {}", b == 0 ? "" : ", ", b, names[b]);
  return "one row per focusing interval; branch: " + branches +
         "; causes: 0 curvature_zero, 1 h_tilde_zero, 2 nonresonance1, 3 nonresonance2, 4 band_edge";
}

JobResult run_study(std::string_view kind, const Document& doc, const RunControl& control, const ModelSource* model) {
  JobResult r;
  try {
    if (is_wave_kind(kind))
      r = run_wave(kind, doc, check(doc, model ? model_study_schema(kind) : study_schema(kind)), model, control.stop);
    else if (is_bright_kind(kind))
      r = run_bright(kind, doc, check(doc, model ? model_study_schema(kind) : study_schema(kind)), model);
    else
      r = kind == "dark continue" ? run_dark(doc, control, model) : run_regime(doc, model);
  } catch (const Interrupted&) {
    throw;
  } catch (const std::runtime_error& e) {  // NumericalFailure, the contact integrator's step underflow
    r = JobResult{PointStatus::numerical_failure, e.what(), {}, 0, {}};
  }
  return r;
}

}  // namespace lrchain::jobs::sweep
