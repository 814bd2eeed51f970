// The "bright floquet" and "bright continue" sweep jobs (bright_study.hpp): the bright-breather job's
// config read from [bright], run, and its result reduced to scalars and rows.
#include "bright_study.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>

#include <fmt/format.h>

#include "lrchain/errors.hpp"
#include "lrchain/jobs/bright_breather_job.hpp"
#include "lrchain/jobs/bright_breather_schema.hpp"
#include "lrchain/sim/bright/bright_seed.hpp"
#include "model_jobs.hpp"
#include "study_options.hpp"

namespace lrchain::jobs::sweep {

using namespace lrchain::config;
using jobs::bright_breather::BrightBreatherConfig;
using jobs::bright_breather::BrightBreatherResult;

namespace {

constexpr double no_value = std::numeric_limits<double>::quiet_NaN();

// The bright job's subcommand of a sweep kind: "floquet" or "continue".
std::string step_of(std::string_view kind) { return kind == "bright continue" ? "continue" : "floquet"; }

// The name a refused [bright] key goes by in a point's reason.
std::string bright_key(const Document& doc, std::string_view key) { return fmt::format("[bright] {} in {}", key, doc.source()); }

// `e` re-raised naming "[bright] KEY in FILE" (the Config key spelled as [bright] names it, omega_b as
// edge_offset when that placed it), its text kept.
[[noreturn]] void rethrow_as_key(const Document& doc, const InvalidParameter& e, bool edge_offset) {
  throw table_key_error(doc, "bright", e, jobs::bright_breather::bright_breather_options(),
                        e.parameter() == "omega_b" && edge_offset ? "edge_offset" : "");
}

// [bright] into the job's config (floquet or branch step) at the point's model, with the job's checks;
// edge_offset places omega_b = omega + sign(h_tilde) edge_offset at the first focusing edge of `branch`.
BrightBreatherConfig read_bright(std::string_view kind, const Document& doc, const CheckedTable& root, const PointModel& p) {
  BrightBreatherConfig c;
  c.step = kind == "bright continue" ? jobs::bright_breather::BrightStep::branch : jobs::bright_breather::BrightStep::floquet;
  c.model = &*p.model;
  c.kernels = p.kernels;
  const CheckedTable b = *root.table("bright");
  const std::optional<double> omega_b = b.number("omega_b"), edge_offset = b.number("edge_offset");
  if (omega_b.has_value() == edge_offset.has_value())
    throw InvalidParameter(bright_key(doc, "omega_b"), "give exactly one of 'omega_b' and 'edge_offset'");
  b.read("branch", c.branch);
  b.read("center", c.center);
  b.read("start", c.start);
  b.read("coupling", c.coupling);
  std::int64_t integer = 0;
  if (b.read("sites", integer)) c.sites = Index(integer);
  if (b.read("max_iterations", integer)) c.max_iterations = Index(integer);
  b.read("tolerance", c.tolerance);
  b.read("tail_tolerance", c.tail_tolerance);
  b.read("unit_tolerance", c.unit_tolerance);
  if (c.step == jobs::bright_breather::BrightStep::branch) {
    if (b.read("points", integer)) c.points = Index(integer);
    b.read("ds", c.ds);
    b.read("parameter", c.parameter);
    if (double to = 0; b.read("to", to)) c.to = to;
    b.read("floquet", c.branch_floquet);
  }
  if (edge_offset) {
    try {  // an unknown branch, or no focusing edge: the start edge_offset asks for does not exist
      const std::optional<Index> given = c.branch.empty() ? std::nullopt : std::optional(p.model->branch(c.branch));
      const NlsCoefficients k = sim::bright::first_focusing_edge(*p.model, given).nls;
      c.omega_b = k.omega + (k.h_tilde > 0 ? *edge_offset : -*edge_offset);
    } catch (const InvalidParameter& e) {
      throw table_key_error(doc, "bright", e, {}, c.branch.empty() ? "edge_offset" : "branch");
    }
  } else {
    c.omega_b = *omega_b;
  }
  try {
    jobs::bright_breather::validate(c);
  } catch (const InvalidParameter& e) {
    rethrow_as_key(doc, e, edge_offset.has_value());
  }
  return c;
}

// Stability code of a breather's multipliers (the trivial ones removed): 0 stable, + 1 real > 1,
// + 2 real < -1, + 4 complex off the unit circle (as the "dark continue" rows).
double stability_code(const sim::bright::BrightFloquet& f) {
  const auto& m = f.multipliers;
  return double((m.real_instability ? 1 : 0) + (m.period_doubling ? 2 : 0) + (m.oscillatory ? 4 : 0));
}

// The scalars of one breather: the Newton solve, the profile, the edge and (floquet) its multipliers.
std::vector<double> breather_scalars(const BrightBreatherResult& r) {
  const bool solved = r.newton.converged;
  const double residual = r.newton.history.empty() ? no_value : r.newton.history.back().residual;
  std::vector<double> s{r.config.omega_b,
                        r.edge.nls.omega,
                        r.edge.theta,
                        solved ? 1.0 : 0.0,
                        r.newton.history.empty() ? 0.0 : double(r.newton.history.size() - 1),
                        residual,
                        solved ? r.profile.peak : no_value,
                        solved ? r.profile.width : no_value,
                        solved ? r.profile.norm_squared : no_value,
                        solved ? r.profile.tail : no_value,
                        solved ? r.seed_difference : no_value};
  const sim::bright::BrightFloquet* f = r.floquet ? &*r.floquet : nullptr;
  s.insert(s.end(), {f ? (f->stable ? 1.0 : 0.0) : no_value, f ? stability_code(*f) : no_value,
                     f ? f->max_nontrivial_modulus : no_value, f ? f->unit_circle_defect : no_value,
                     f ? f->multipliers.pairing_defect : no_value, f ? f->det_defect : no_value,
                     f ? f->trivial_distance : no_value});
  return s;
}

const std::vector<std::string>& breather_scalar_names() {
  static const std::vector<std::string> n{
      "omega_b",        "omega_edge",     "theta_edge",        "converged",          "newton_iterations",
      "residual",       "peak",           "width",             "norm_squared",       "tail",
      "seed_difference", "stable",        "stability",         "max_nontrivial_modulus", "unit_circle_defect",
      "pairing_defect", "det_defect",     "trivial_distance"};
  return n;
}

const std::vector<std::string>& branch_scalar_names() {
  static const std::vector<std::string> n{
      "start_omega_b", "omega_edge", "converged", "newton_iterations", "residual", "branch_points", "turning_points",
      "first_turning_point", "parameter_low", "parameter_high", "peak_low", "peak_high", "stable_points",
      "real_unstable_points", "period_doubling_points", "oscillatory_unstable_points", "stable_windows",
      "unstable_windows", "first_unstable", "max_nontrivial_modulus", "folds", "branch_point_crossings",
      "period_doubling_crossings", "krein_collisions", "first_bifurcation", "window_low", "window_high"};
  return n;
}

// The branch reduced to branch_scalar_names() and one row per point (bright_row_names).
void reduce_branch(const BrightBreatherResult& br, JobResult& r) {
  const auto& pts = br.branch.points;
  const bool floquet = br.branch_floquets.size() == pts.size();
  double low = no_value, high = no_value, peak_low = no_value, peak_high = no_value, max_mod = floquet ? 0 : no_value,
         first_unstable = no_value;
  int stable = 0, real = 0, doubling = 0, oscillatory = 0, stable_windows = 0, unstable_windows = 0, part = 0;
  for (std::size_t i = 0; i < pts.size(); ++i) {
    const auto& p = pts[i];
    const auto& profile = br.branch_profiles.at(i);
    low = i == 0 ? p.parameter : std::min(low, p.parameter);
    high = i == 0 ? p.parameter : std::max(high, p.parameter);
    peak_low = i == 0 ? profile.peak : std::min(peak_low, profile.peak);
    peak_high = i == 0 ? profile.peak : std::max(peak_high, profile.peak);
    if (i > 0 && (p.tangent_omega > 0) != (pts[i - 1].tangent_omega > 0)) ++part;  // as the job's turning points
    double ok = no_value, code = no_value, modulus = no_value;
    if (floquet) {
      const auto& f = br.branch_floquets[i];
      ok = f.stable ? 1 : 0;
      code = stability_code(f);
      modulus = f.max_nontrivial_modulus;
      stable += f.stable;
      real += f.multipliers.real_instability;
      doubling += f.multipliers.period_doubling;
      oscillatory += f.multipliers.oscillatory;
      max_mod = std::max(max_mod, modulus);
      if (!f.stable && std::isnan(first_unstable)) first_unstable = p.parameter;
      if (i == 0 || br.branch_floquets[i - 1].stable != f.stable) (f.stable ? stable_windows : unstable_windows) += 1;
    }
    r.rows.insert(r.rows.end(), {p.omega_b, p.parameter, profile.peak, profile.norm_squared, profile.width, p.residual,
                                 double(p.iterations), ok, code, modulus, double(part)});
  }
  const auto count = [&](const char* kind) {
    return double(std::count_if(br.bifurcations.begin(), br.bifurcations.end(), [&](const auto& b) { return b.kind == kind; }));
  };
  const auto when = [&](double n) { return floquet ? n : no_value; };
  r.scalars = {br.config.omega_b, br.edge.nls.omega, 1.0, double(br.newton.history.size() - 1),
               br.newton.history.back().residual, double(pts.size()), double(br.branch.turning_points.size()),
               br.branch.turning_points.empty() ? no_value : br.branch.turning_points.front(), low, high, peak_low,
               peak_high, when(stable), when(real), when(doubling), when(oscillatory), when(stable_windows),
               when(unstable_windows), first_unstable, max_mod, count("fold"), when(count("branch_point")),
               when(count("period_doubling")), when(count("krein_collision")),
               br.bifurcations.empty() ? no_value : br.bifurcations.front().omega_b, br.window_low,
               std::isfinite(br.window_high) ? br.window_high : no_value};
}

}  // namespace

std::shared_ptr<const TableSchema> bright_table(std::string_view kind) {
  std::vector<KeySchema> keys;
  for (const JobOption& o : jobs::bright_breather::bright_breather_options()) {
    if (!sweep_option(o, step_of(kind))) continue;
    keys.push_back(sweep_option_key(o));
    if (o.key == "omega_b") keys.back() = number(o.python, NumberRange::any(), "none", o.doc + "; or edge_offset");
  }
  keys.push_back(number("edge_offset", NumberRange::positive(), "none",
                        "start at omega_b = omega(edge) + sign(h_tilde) edge_offset, the first focusing edge of branch "
                        "(none: of the model, theta = pi first), instead of omega_b (for sweeps over the model)"));
  return std::make_shared<const TableSchema>(
      TableSchema{kind == "bright continue"
                      ? "an exact bright breather continued in omega_b or a model parameter, as `lrchain bright continue`"
                      : "an exact bright breather and its Floquet stability, as `lrchain bright floquet`",
                  keys, std::nullopt});
}

std::vector<std::string> bright_scalar_names(std::string_view kind) {
  return kind == "bright continue" ? branch_scalar_names() : breather_scalar_names();
}

std::vector<std::string> bright_row_names(std::string_view kind) {
  if (kind != "bright continue") return {};
  return {"omega_b", "parameter", "peak", "norm_squared", "width", "residual", "iterations", "stable", "stability",
          "max_modulus", "part"};
}

std::string bright_rows_legend(std::string_view kind) {
  if (kind != "bright continue") return "";
  return "one row per branch point in continuation order; parameter: the continued one's value (omega_b or the "
         "model's); stable, stability (0 stable, +1 real, +2 period doubling, +4 oscillatory) and max_modulus (the "
         "largest non-trivial |lambda|): NaN without Floquet; part: 0 before the first turning point, +1 after each";
}

void check_bright_base(std::string_view kind, const Document& doc, const CheckedTable& root, const ModelSource* source) {
  const PointModel p = point_model(root, source);
  read_bright(kind, doc, root, p);
}

JobResult run_bright(std::string_view kind, const Document& doc, const CheckedTable& root, const ModelSource* source) {
  const PointModel p = point_model(root, source);
  const BrightBreatherConfig c = read_bright(kind, doc, root, p);
  BrightBreatherResult b;
  try {
    b = jobs::bright_breather::run(c);
  } catch (const InvalidParameter& e) {  // a branch's `to` outside the window found at run time
    rethrow_as_key(doc, e, false);
  }
  JobResult r;
  const std::optional<std::string> failure = jobs::bright_breather::failure(b);
  if (kind == "bright continue" && !failure) {
    reduce_branch(b, r);
  } else {
    r.scalars = breather_scalars(b);
    if (kind == "bright continue") {  // the breather's own scalars where the branch's names them
      const std::vector<double> one = r.scalars;
      r.scalars.assign(branch_scalar_names().size(), no_value);
      r.scalars[0] = one[0], r.scalars[1] = one[1], r.scalars[2] = one[3], r.scalars[3] = one[4], r.scalars[4] = one[5];
    }
  }
  r.status = failure ? PointStatus::numerical_failure : PointStatus::ok;
  if (failure) r.reason = *failure;
  return r;
}

}  // namespace lrchain::jobs::sweep
