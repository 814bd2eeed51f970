// to_json(BrightBreatherResult): the summary `lrchain bright` prints (bright_breather_job.hpp).
#include <cmath>
#include <complex>

#include "lrchain/jobs/bright_breather_job.hpp"
#include "lrchain/model_json.hpp"
#include "lrchain/provenance_json.hpp"

namespace lrchain::jobs::bright_breather {

using nlohmann::json;

namespace {

json complex_list(const std::vector<std::complex<double>>& values) {
  json list = json::array();
  for (auto l : values) list.push_back({l.real(), l.imag()});
  return list;
}

json profile_json(const sim::bright::BrightProfile& p) {
  return {{"peak", p.peak}, {"peak_site", p.peak_site}, {"tail", p.tail}, {"width", p.width},
          {"norm_squared", p.norm_squared}, {"localized", p.localized},
          {"reason", p.reason.empty() ? json(nullptr) : json(p.reason)}};
}

json floquet_json(const sim::bright::BrightFloquet& f) {
  return {{"stable", f.stable},
          {"kind", f.multipliers.kind()},
          {"trivial_expected", f.trivial_expected},
          {"trivial_found", f.trivial_found},
          {"trivial", complex_list(f.trivial)},
          {"trivial_distance", f.trivial_distance},
          {"max_nontrivial_modulus", f.max_nontrivial_modulus},
          {"unit_circle_defect", f.unit_circle_defect},
          {"pairing_defect", f.multipliers.pairing_defect},
          {"det_defect", f.det_defect},
          {"multipliers", complex_list(f.multipliers.multipliers)}};
}

// Per multiplier on the upper unit circle: angle, modulus and Krein signature (null: undetermined, the
// strain lift does not close).
json krein_json(const std::vector<sim::bright::KreinMultiplier>& multipliers) {
  json krein = json::array();
  for (const auto& m : multipliers)
    krein.push_back({{"angle", std::arg(m.lambda)}, {"modulus", std::abs(m.lambda)},
                     {"signature", m.signature != 0 ? json(m.signature) : json(nullptr)}});
  return krein;
}

json edge_json(const BrightEdge& e) {
  return {{"branch", e.branch}, {"theta", e.theta}, {"omega", e.nls.omega}, {"curvature", e.nls.curvature},
          {"h_tilde", e.nls.h_tilde}, {"lambda", e.mean_flow ? json(e.nls.lambda) : json(nullptr)},
          {"seed_amplitude", e.amplitude}, {"seed_inverse_width", e.inverse_width}};
}

// The continuation: why it stopped, the non-resonant window, turning points, per point omega_b,
// the profile's peak, norm and width, the corrector's iterations and (with Floquet) the stability and
// the Krein signatures (angle of each multiplier on the upper unit circle, its signature), and
// the bifurcations (kind, index, omega_b, norm_squared, bracket; a located crossing: its error bound in
// omega_b and the crossing multiplier, re and im, and its modulus).
json branch_json(const BrightBreatherResult& r) {
  json points = json::array();
  for (std::size_t k = 0; k < r.branch.points.size(); ++k) {
    const auto& p = r.branch.points[k];
    const auto& profile = r.branch_profiles.at(k);
    json point = {{"omega_b", p.omega_b}, {"peak", profile.peak}, {"norm_squared", profile.norm_squared},
                  {"width", profile.width}, {"residual", p.residual}, {"corrector_iterations", p.iterations},
                  {"stable", nullptr}, {"max_nontrivial_modulus", nullptr}};
    if (r.config.parameter != "omega_b") point[r.config.parameter] = p.parameter;  // the continued parameter's value
    if (k < r.branch_floquets.size()) {
      point["stable"] = r.branch_floquets[k].stable;
      point["max_nontrivial_modulus"] = r.branch_floquets[k].max_nontrivial_modulus;
    }
    point["krein"] = k < r.branch_krein.size() ? krein_json(r.branch_krein[k]) : json(nullptr);  // no Floquet: none
    points.push_back(point);
  }
  json bifurcations = json::array();
  for (const auto& b : r.bifurcations)
    bifurcations.push_back({{"kind", b.kind}, {"index", b.index}, {"omega_b", b.omega_b},
                            {"norm_squared", b.norm_squared}, {"omega_low", b.omega_low}, {"omega_high", b.omega_high},
                            {"located", b.located}, {"location_error", b.located ? json(b.location_error) : json(nullptr)},
                            {"multiplier", b.multiplier ? json({b.multiplier->real(), b.multiplier->imag()}) : json(nullptr)},
                            {"multiplier_modulus", b.multiplier ? json(std::abs(*b.multiplier)) : json(nullptr)}});
  return {{"parameter", r.config.parameter},
          {"to", r.config.to ? json(*r.config.to) : json(nullptr)},
          {"points", r.branch.points.size()},
          {"stop_reason", r.branch.stop_reason},
          {"window", {r.window_low, std::isfinite(r.window_high) ? json(r.window_high) : json(nullptr)}},
          {"turning_points", r.branch.turning_points},
          {"branch_points", points},
          {"bifurcations", bifurcations}};
}

const char* step_name(BrightStep step) {
  return step == BrightStep::floquet ? "floquet"
         : step == BrightStep::branch ? "continue"
         : step == BrightStep::evolve ? "evolve"
                                      : "solve";
}

// The evolution: periods, the profile and energy drift, the measured growth rate of the deviation
// (its fit window) beside the one the largest multiplier predicts, and the perturbation of the start.
json evolution_json(const BrightBreatherResult& r) {
  const BrightBreatherConfig& c = r.config;
  const sim::bright::BrightEvolution& e = *r.evolution;
  json perturbation = nullptr;
  if (c.perturb != "none") {
    perturbation = {{"kind", c.perturb}, {"size", c.perturb_size}};
    if (c.perturb == "random") perturbation["seed"] = c.seed;
    if (c.perturb == "unstable") {
      perturbation["multiplier"] = {r.perturbation.multiplier.real(), r.perturbation.multiplier.imag()};
      perturbation["multiplier_modulus"] = std::abs(r.perturbation.multiplier);
    }
  }
  return {{"periods", c.periods},
          {"period", e.period},
          {"t_end", e.samples.back().t},
          {"profile_drift", e.profile_drift},
          {"final_deviation", e.samples.back().deviation},
          {"energy", e.has_energy ? json(e.samples.front().energy) : json(nullptr)},
          {"energy_drift", e.has_energy ? json(e.energy_drift) : json(nullptr)},
          {"growth_rate", e.growth_rate ? json(*e.growth_rate) : json(nullptr)},
          {"growth_fit_periods", e.growth_rate ? json(e.fit_last) : json(nullptr)},
          {"predicted_growth_rate", r.predicted_growth_rate},
          {"perturbation", perturbation}};
}

// Newton's start: nls, or anti-continuum with the uncoupled orbit's amplitude and the continuation in
// the coupling (its points, and the value reached).
json start_json(const BrightBreatherResult& r) {
  const BrightBreatherConfig& c = r.config;
  if (c.start != "anti-continuum") return {{"kind", "nls"}};
  const auto& points = r.anti_continuum_branch.points;
  return {{"kind", "anti-continuum"},
          {"coupling", c.coupling},
          {"amplitude", r.anti_continuum_amplitude},
          {"continuation_points", points.size()},
          {"reached", points.empty() ? json(0.0) : json(points.back().parameter)}};
}

}  // namespace

json to_json(const BrightBreatherResult& r) {
  const BrightBreatherConfig& c = r.config;
  json bands = json::array();
  for (const auto& b : r.bands) bands.push_back({{"branch", b.branch}, {"lowest", b.lowest}, {"highest", b.highest}});
  json residuals = json::array();
  for (const auto& record : r.newton.history) residuals.push_back(record.residual);
  json j = {{"model", model_json(*c.model)},
            {"step", step_name(c.step)},
            {"omega_b", c.omega_b},
            {"center", c.center},
            {"sites", c.sites},
            {"bands", bands},
            {"harmonics_checked", r.harmonics_checked},
            {"edge", edge_json(r.edge)},
            {"lattice_form", r.edge.mean_flow ? "strain" : "displacement"},
            {"variables", r.edge.variable_meanings},
            {"one_sided_contacts", r.edge.one_sided_contacts},
            {"newton_converged", r.newton.converged},
            {"newton_iterations", r.newton.history.empty() ? 0 : r.newton.history.size() - 1},
            {"newton_residuals", residuals},
            {"start", start_json(r)},
            {"seed_profile", profile_json(r.seed_profile)},
            {"seconds", r.seconds},
            {"failure", nullptr},
            {"provenance", provenance_json()}};
  if (r.newton.converged) {
    j["profile"] = profile_json(r.profile);
    j["seed_difference"] = r.seed_difference;
  }
  if (r.floquet) j["floquet"] = floquet_json(*r.floquet);
  if (r.floquet && c.step == BrightStep::floquet) j["floquet"]["krein"] = krein_json(r.krein);
  if (r.krylov) j["krylov"] = to_json(*r.krylov);
  if (r.evolution) j["evolution"] = evolution_json(r);
  if (c.step == BrightStep::branch && r.newton.converged && r.rejected.empty()) j["branch"] = branch_json(r);
  if (const auto f = failure(r))
    j["failure"] = {{"kind", !r.start_failure.empty() ? "start" : r.newton.converged ? "not_a_bright_breather" : "newton"},
                    {"message", *f}};
  return j;
}

}  // namespace lrchain::jobs::bright_breather
