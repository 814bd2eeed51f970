// The coefficients job's result as JSON and as text (lrchain/jobs/coeffs.hpp).
#include <cmath>
#include <fmt/core.h>

#include "lrchain/coefficient_check.hpp"
#include "lrchain/jobs/coeffs.hpp"
#include "lrchain/model_json.hpp"
#include "lrchain/provenance_json.hpp"

namespace lrchain::jobs {

namespace {

nlohmann::json number_or_null(double v) { return std::isfinite(v) ? nlohmann::json(v) : nlohmann::json(nullptr); }

// The coefficients; a refused evaluation or a pole found by the limit adds "singular" (the reason), a
// limit "evaluation": "limit".
nlohmann::json coefficients_json(const NlsCoefficients& c) {
  nlohmann::json j = {{"theta", c.theta},
          {"omega", number_or_null(c.omega)},
          {"group_velocity", number_or_null(c.group_velocity)},
          {"curvature", number_or_null(c.curvature)},
          {"gamma", number_or_null(c.gamma)},
          {"beta", number_or_null(c.beta)},
          {"h", number_or_null(c.h)},
          {"lambda", number_or_null(c.lambda)},
          {"h_tilde", number_or_null(c.h_tilde)},
          {"nonresonance1", number_or_null(c.nonresonance1)},
          {"nonresonance2", number_or_null(c.nonresonance2)},
          {"regime", std::string(to_string(c.regime))}};
  if (c.evaluation != CoefficientEvaluation::direct && c.regime == Regime::singular) j["singular"] = std::string(singular_reason(c));
  if (c.evaluation == CoefficientEvaluation::limit) j["evaluation"] = "limit";
  return j;
}

std::string value_text(double v) { return std::isfinite(v) ? fmt::format("{:.17g}", v) : "singular"; }

// One wavenumber of the resonant chain, each row with the paper's equation.
std::string resonant_chain_text(const CoeffsResult& r, const Params& p, std::string (*cite)(const std::string&)) {
  const NlsCoefficients& c = r.coefficients;
  std::string text = fmt::format("{} branch, theta = {:.12g} (alpha={:g}, delta0={:.12g}, kappa={:g}, rho={:.12g})\n",
                                 r.branch, c.theta, p.alpha, p.delta0, p.kappa, p.rho);
  const auto row = [&](const char* name, const char* eq, double v) {
    text += fmt::format("  {:<15} {:<22} {}\n", name, cite(eq), value_text(v));
  };
  row("omega", "eq:disp1d", c.omega);
  row("group_velocity", "c, eq:c", c.group_velocity);
  row("curvature", "omega'', eq:ppOmega", c.curvature);
  row("gamma", "eq:gamma", c.gamma);
  row("beta", "eq:ppOmega", c.beta);
  row("h", "eq:h", c.h);
  row("lambda", "eq:lambda", c.lambda);
  row("h_tilde", "h - lambda beta", c.h_tilde);
  row("nonresonance1", "eq:nonresonance1", c.nonresonance1);
  row("nonresonance2", "eq:nonresonance2", c.nonresonance2);
  return text + fmt::format("  {:<15} {:<22} {}\n", "regime", "sign(omega'' h_tilde)", to_string(c.regime));
}

// One wavenumber of any other model.
std::string model_text(const CoeffsResult& r) {
  const NlsCoefficients& c = r.coefficients;
  const ModelDefinition& d = r.model.definition();
  std::string parameters;
  for (std::size_t i = 0; i < d.parameters.size(); ++i)
    parameters += fmt::format("{}{}={:.12g}", i ? ", " : "", d.parameters[i].name, r.model.inputs()[i]);
  std::string text = fmt::format("model {}, {} branch, theta = {:.12g} ({})\n", d.name, r.branch, c.theta, parameters);
  const auto row = [&](const char* name, double v) { text += fmt::format("  {:<15} {}\n", name, value_text(v)); };
  row("omega", c.omega);
  row("group_velocity", c.group_velocity);
  row("curvature", c.curvature);
  row("gamma", c.gamma);
  row("beta", c.beta);
  row("h", c.h);
  if (d.mean_flow) row("lambda", c.lambda);
  else text += fmt::format("  {:<15} {}\n", "lambda", "none (on-site model: no mean flow)");
  row("h_tilde", c.h_tilde);
  row("nonresonance1", c.nonresonance1);
  if (d.mean_flow) row("nonresonance2", c.nonresonance2);
  text += fmt::format("  {:<15} {}\n", "regime", to_string(c.regime));
  if (c.evaluation != CoefficientEvaluation::direct && c.regime == Regime::singular)
    text += fmt::format("  {:<15} {}\n", "singular", singular_reason(c));
  if (c.evaluation == CoefficientEvaluation::limit)
    text += fmt::format("  {:<15} {}\n", "evaluation", "limit (the derived expressions are 0/0 here)");
  return text;
}

// One column of the table: a space and 12 characters, right-aligned under its header.
std::string cell(double v) { return std::isfinite(v) ? fmt::format(" {:>12.6g}", v) : fmt::format(" {:>12}", "singular"); }

// The table: a title, then per branch one aligned row per wavenumber.
std::string table_text(const CoeffsResult& r) {
  const std::optional<Params>& p = r.model.resonant_chain_params();
  std::string text = p ? fmt::format("NLS coefficients, alpha={:g}, delta0={:.6g}, kappa={:g}, rho={:.6g} (derived by "
                                     "lrchain-derive)\n", p->alpha, p->delta0, p->kappa, p->rho)
                       : "NLS coefficients of model " + r.model.name() + "\n";
  for (const CoeffsTableBranch& branch : r.table) {
    text += fmt::format("\n{} branch\n{:>7} {:>12} {:>12} {:>12} {:>12} {:>12} {:>12} {:>12}  {}\n", branch.name, "theta",
                        "omega", "c", "omega''", "beta", "h", "lambda", "h_tilde", "regime");
    for (std::size_t i = 0; i < branch.rows.size(); ++i) {
      const NlsCoefficients& c = branch.rows[i];
      text += fmt::format("{:>7}{}{}{}{}{}{}{}  {}\n", table_thetas()[i].label, cell(c.omega), cell(c.group_velocity),
                          cell(c.curvature), cell(c.beta), cell(c.h),
                          branch.mean_flow ? cell(c.lambda) : fmt::format(" {:>12}", "none"), cell(c.h_tilde),
                          to_string(c.regime));
    }
  }
  return text;
}

}  // namespace

nlohmann::json to_json(const CoeffsResult& result) {
  if (!result.is_table) {
    nlohmann::json j = coefficients_json(result.coefficients);
    j["branch"] = result.branch;
    j["model"] = model_json(result.model);
    j["provenance"] = provenance_json();
    return j;
  }
  nlohmann::json branches = nlohmann::json::array();
  for (const CoeffsTableBranch& branch : result.table) {
    nlohmann::json rows = nlohmann::json::array();
    for (std::size_t i = 0; i < branch.rows.size(); ++i) {
      nlohmann::json row = coefficients_json(branch.rows[i]);
      row["theta_label"] = table_thetas()[i].label;
      if (!branch.mean_flow) row["lambda"] = nullptr;
      rows.push_back(row);
    }
    branches.push_back({{"branch", branch.name}, {"rows", rows}});
  }
  return {{"model", model_json(result.model)}, {"branches", branches}, {"provenance", provenance_json()}};
}

std::string to_text(const CoeffsResult& result, std::string (*cite)(const std::string& text)) {
  if (result.is_table) return table_text(result);
  if (const std::optional<Params>& p = result.model.resonant_chain_params()) return resonant_chain_text(result, *p, cite);
  return model_text(result);
}

}  // namespace lrchain::jobs
