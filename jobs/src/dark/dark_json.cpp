// to_json(DarkResult) and failure(DarkResult): the summary `lrchain dark` prints (dark_job.hpp).
#include <algorithm>
#include <cmath>
#include <numbers>

#include <fmt/format.h>

#include "lrchain/jobs/dark_job.hpp"
#include "lrchain/model_json.hpp"
#include "lrchain/provenance_json.hpp"

namespace lrchain::jobs::dark {

using nlohmann::json;
using namespace lrchain::sim::dark;

namespace {

json floquet_json(const FloquetResult& f) {
  json multipliers = json::array();
  for (auto l : f.multipliers) multipliers.push_back({l.real(), l.imag()});
  return {{"kind", f.kind()},
          {"max_modulus", f.max_modulus},
          {"max_real", f.max_real},
          {"max_period_doubling", f.max_period_doubling},
          {"max_oscillatory", f.max_oscillatory},
          {"near_one", f.near_one},
          {"pairing_defect", f.pairing_defect},
          {"log_det", f.log_det},
          {"multipliers", multipliers}};
}

json measures_json(const DarkMeasures& m) {
  return {{"norm_squared", m.norm_squared}, {"K_x", m.K_x}, {"K_y", m.K_y}, {"C_x", m.C_x},
          {"C_y", m.C_y}, {"E_b", m.E_b}, {"max_strain", m.max_strain}};
}

// A count, or null where there is none (a smooth model's contact changes).
json count_json(const std::optional<Index>& count) { return count ? json(*count) : json(nullptr); }

// The model, the options, the band edge and the Newton history; "failure" null.
json base_json(const DarkResult& r) {
  const DarkConfig& c = r.config;
  json residuals = json::array();
  for (const auto& record : r.newton.history) residuals.push_back(record.residual);
  if (!r.model_file())
    return {{"model", model_json(resonant_chain_model(c.params))},
            {"branch", r.edge.branch}, {"center", c.center}, {"sites", dark_sites(c)}, {"mode", c.mode},
            {"omega_b", c.omega_b}, {"omega_edge", r.edge.omega},
            {"newton_converged", r.newton.converged}, {"newton_residuals", residuals}, {"failure", nullptr},
            {"provenance", provenance_json()}};
  const DarkEdge& e = r.edge;
  return {{"model", model_json(*c.model)}, {"branch", e.branch},
          {"theta", e.theta}, {"center", c.center}, {"sites", dark_sites(c)}, {"mode", c.mode},
          {"omega_b", c.omega_b}, {"omega_edge", e.omega}, {"curvature", e.curvature},
          {"h_tilde", e.h_tilde}, {"lambda", e.mean_flow ? json(e.lambda) : json(nullptr)},
          {"lattice_form", e.mean_flow ? "strain" : "displacement"}, {"variables", e.variable_meanings},
          {"one_sided_contacts", e.one_sided_contacts},
          {"contact_changes_located", !e.one_sided_contacts.empty()},
          {"newton_converged", r.newton.converged},
          {"newton_iterations", r.newton.history.empty() ? 0 : r.newton.history.size() - 1},
          {"newton_residuals", residuals}, {"failure", nullptr}, {"provenance", provenance_json()}};
}

// The branch: its points, why it stopped, turning points; a model's points with their contact changes.
void branch_json(const DarkResult& r, json& j) {
  const BranchResult& br = r.branch;
  j["points"] = br.points.size();
  j["stop_reason"] = br.stop_reason;
  j["stop"] = to_string(br.stop);
  j["parameter"] = r.config.parameter;
  j["to"] = r.config.to ? json(*r.config.to) : json(nullptr);
  j["turning_points"] = br.turning_points;
  json folds = json::array();  // interpolated between the points on either side (continuation.hpp)
  for (const auto& f : br.folds)  // at the continued parameter's value (omega_b, or a model parameter)
    folds.push_back({{r.config.parameter, f.omega_b}, {"norm_squared", f.norm_squared}, {"after_point", f.after},
                     {"fraction", f.fraction}});
  j["folds"] = folds;
  j["interrupted"] = br.interrupted;
  double worst = 0;
  for (const auto& b : br.points) worst = std::max(worst, b.measures.E_b);
  j["max_E_b"] = worst;
  if (r.model_file()) {
    json points = json::array();
    for (const auto& b : br.points)
      points.push_back({{"omega_b", b.omega_b}, {"E_b", b.measures.E_b},
                        {"contact_changes_per_period", count_json(b.contact_changes_per_period)}});
    if (r.config.parameter != "omega_b")  // each point's value of the continued parameter
      for (std::size_t i = 0; i < br.points.size(); ++i) points[i][r.config.parameter] = br.points[i].parameter;
    j["branch_points"] = points;
    j["symmetry"] = r.symmetry.empty() ? json(nullptr) : json(r.symmetry);
    j["contact_changes_per_period"] = points.empty() ? json(nullptr) : points.front()["contact_changes_per_period"];
  }
}

// The evolution per period: E_b, C_x, the breather's position and depth at the first and last period.
void evolution_json(const DarkResult& r, json& j) {
  const DarkEvolution& e = r.evolution;
  const auto& first = e.periods.front();
  const auto& last = e.periods.back();
  double max_shift = 0, max_E = 0;
  for (const auto& p : e.periods) {
    max_shift = std::max(max_shift, std::abs(p.position - first.position));
    max_E = std::max(max_E, p.E_b);
  }
  j["t_end"] = last.t;
  j["periods"] = e.periods.size();
  j["period"] = e.period;
  j["E_b_first_period"] = first.E_b;
  j["E_b_end"] = last.E_b;
  j["E_b_max"] = max_E;
  j["C_x_first_period"] = first.C_x;
  j["C_x_end"] = last.C_x;
  j["position_first_period"] = first.position;
  j["position_end"] = last.position;
  j["centre_drift"] = std::abs(last.position - first.position);
  j["max_centre_shift"] = max_shift;
  j["depth_first_period"] = first.depth;
  j["depth_end"] = last.depth;
  if (!r.model_file()) j["max_strain"] = e.max_strain;
  j["samples_per_period"] = r.config.samples;
  const DarkConfig& c = r.config;  // the perturbation the start carried (perturb none: null)
  if (c.perturb == "none") {
    j["perturbation"] = nullptr;
  } else {
    json p = {{"kind", c.perturb}, {"size", c.perturb_size}};
    if (c.perturb == "random") p["seed"] = c.seed;
    if (c.perturb == "unstable") p["multiplier"] = {r.perturbation.multiplier.real(), r.perturbation.multiplier.imag()};
    if (c.perturb == "unstable") p["multiplier_modulus"] = std::abs(r.perturbation.multiplier);
    j["perturbation"] = p;
  }
}

}  // namespace

std::optional<std::string> failure(const DarkResult& r) {
  if (!r.newton.converged) return newton_failure_message(r.newton, r.config.omega_b);
  if (r.config.step == DarkStep::branch && r.branch.points.size() < 2 && !r.branch.interrupted)
    return "continuation stopped: " + r.branch.stop_reason;  // the corrector failed at once
  if (r.config.step == DarkStep::branch && r.branch.stop == BranchStop::step_too_small)  // it could not go on
    return fmt::format("continuation stopped after {} points: {}", r.branch.points.size(), r.branch.stop_reason);
  return std::nullopt;
}

json to_json(const DarkResult& r) {
  json j = base_json(r);
  if (!r.newton.converged) {
    j["failure"] = {{"kind", "newton"}, {"message", *failure(r)}};
    return j;
  }
  if (r.model_file() && r.config.step != DarkStep::branch)
    j["contact_changes_per_period"] = count_json(r.contact_changes_per_period);
  switch (r.config.step) {
    case DarkStep::branch:
      branch_json(r, j);
      if (const auto f = failure(r)) j["failure"] = {{"kind", "continuation"}, {"message", *f}};
      return j;
    case DarkStep::evolve:
      if (!r.evolution.periods.empty()) evolution_json(r, j);
      return j;
    case DarkStep::solve:
    case DarkStep::floquet:
      break;
  }
  j["measures"] = measures_json(r.measures);
  if (r.model_file() && (!r.edge.mean_flow || r.edge.fields < 2)) j["measures"]["K_y"] = j["measures"]["C_y"] = nullptr;
  if (r.floquet) {
    j["monodromy"] = r.monodromy;
    j["floquet"] = floquet_json(*r.floquet);
  }
  if (r.krylov) j["krylov"] = to_json(*r.krylov);
  return j;
}

}  // namespace lrchain::jobs::dark
