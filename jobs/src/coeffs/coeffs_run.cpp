// The coefficients job's checks and run (lrchain/jobs/coeffs.hpp): one wavenumber through
// coefficients(model, ...), the table through coefficients_batch(); lib takes the resonant chain's
// specialised evaluators for the paper's chain.
#include <array>
#include <cmath>
#include <numbers>

#include "lrchain/coefficients_batch.hpp"
#include "lrchain/errors.hpp"
#include "lrchain/jobs/coeffs.hpp"

namespace lrchain::jobs {

namespace {

constexpr std::size_t kTableRows = 6;

// The coefficients of one branch at the table's wavenumbers, one batch evaluation.
CoeffsTableBranch table_branch(const Model& model, Index branch) {
  std::array<double, kTableRows> theta{}, values[kCoefficientColumnCount];
  std::array<std::int8_t, kTableRows> regime{};
  for (std::size_t i = 0; i < kTableRows; ++i) theta[i] = table_thetas()[i].theta;
  CoefficientColumns columns{};
  for (int k = 0; k < kCoefficientColumnCount; ++k) columns.field[k] = values[k].data();
  columns.regime = regime.data();
  coefficients_batch(model, branch, theta, columns);
  const ModelDefinition& d = model.definition();
  CoeffsTableBranch result{d.branch_names[static_cast<std::size_t>(branch)], d.mean_flow, {}};
  for (std::size_t i = 0; i < kTableRows; ++i) {
    NlsCoefficients c;
    c.theta = theta[i];
    c.omega = values[0][i];
    c.group_velocity = values[1][i];
    c.curvature = values[2][i];
    c.gamma = values[3][i];
    c.beta = values[4][i];
    c.h = values[5][i];
    c.lambda = values[6][i];
    c.h_tilde = values[7][i];
    c.nonresonance1 = values[8][i];
    c.nonresonance2 = values[9][i];
    c.regime = static_cast<Regime>(regime[i]);
    result.rows.push_back(c);
  }
  return result;
}

// The branch index of `name`: the resonant chain's spellings (optical, opt, +, acoustic, acs, -)
// for the chain, the model's branch names otherwise (none: the model's only branch).
Index branch_index(const Model& model, const std::string& name) {
  if (model.resonant_chain_params()) return model.branch(to_string(parse_branch(name)));
  return model.branch_or_only(name);
}

}  // namespace

const std::vector<LabelledWavenumber>& table_thetas() {
  static const std::vector<LabelledWavenumber> thetas = {
      {"pi/8", std::numbers::pi / 8},      {"pi/4", std::numbers::pi / 4},      {"pi/2", std::numbers::pi / 2},
      {"3pi/5", 3 * std::numbers::pi / 5}, {"3pi/4", 3 * std::numbers::pi / 4}, {"pi", std::numbers::pi}};
  return thetas;
}

void validate(const CoeffsConfig& config) {
  if (config.model) {
    if (const auto& p = config.model->resonant_chain_params()) validate(*p);
  } else {
    validate(config.params);
  }
  if (config.table) return;  // the table has its own wavenumbers and every branch
  if (!config.theta) throw InvalidParameter("theta", "is required: a wavenumber in (-pi, pi]");
  if (config.branch.empty()) {
    if (!config.model || config.model->resonant_chain_params())
      throw InvalidParameter("branch", "is required: 'optical' or 'acoustic'");
    config.model->branch_or_only("");  // the model's only branch, or "is required" naming its branches
  }
}

CoeffsResult run_coeffs(const CoeffsConfig& config) {
  validate(config);
  CoeffsResult result{config.model ? *config.model : resonant_chain_model(config.params), {}, {}, {}, config.table};
  const Model& model = result.model;
  if (config.table) {
    for (Index b = static_cast<Index>(model.definition().branch_names.size()); b-- > 0;)
      result.table.push_back(table_branch(model, b));
    return result;
  }
  const Index branch = branch_index(model, config.branch);
  result.branch = model.definition().branch_names[static_cast<std::size_t>(branch)];
  if (model.resonant_chain_params())  // the chain's own messages (the zero-frequency mode), as `lrchain coeffs` gives them
    check_resonant_chain_wavenumber(model.resonant_chain_branch(branch), *config.theta);
  result.coefficients = coefficients(model, branch, *config.theta);
  return result;
}

}  // namespace lrchain::jobs
