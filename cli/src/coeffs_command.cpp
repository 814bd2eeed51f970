// `lrchain coeffs`: NLS coefficients (eq:c, eq:ppOmega, eq:h, eq:gamma, eq:lambda, eq:h_tilde) at one
// wavenumber, or (--table) the coefficient table of both branches at a few wavenumbers.
#include <cmath>
#include <cstdio>
#include <fmt/core.h>
#include <nlohmann/json.hpp>
#include <numbers>
#include <string>
#include <vector>

#include "commands.hpp"
#include "lrchain/provenance_json.hpp"
#include "lrchain/coefficients.hpp"
#include "lrchain/errors.hpp"
#include "lrchain/model.hpp"
#include "help_text.hpp"
#include "model_option.hpp"
#include "options.hpp"

namespace lrchain::cli {
namespace {

struct CoeffsOptions {
  Params params;
  ModelSelection model;
  double theta = std::numeric_limits<double>::quiet_NaN();
  std::string branch;
  bool json = false;
  bool table = false;
};

nlohmann::json number_or_null(double v) { return std::isfinite(v) ? nlohmann::json(v) : nlohmann::json(nullptr); }

nlohmann::json to_json(const NlsCoefficients& c) {
  return {{"theta", c.theta},
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
}

// One column of the --table output: a space and 12 characters, right-aligned under its header.
std::string cell(double v) { return std::isfinite(v) ? fmt::format(" {:>12.6g}", v) : fmt::format(" {:>12}", "singular"); }

void print_text(const NlsCoefficients& c, Branch b, const Params& p) {
  fmt::print("{} branch, theta = {:.12g} (alpha={:g}, delta0={:.12g}, kappa={:g}, rho={:.12g})\n", to_string(b),
             c.theta, p.alpha, p.delta0, p.kappa, p.rho);
  const auto row = [](const char* name, const char* eq, double v) {
    fmt::print("  {:<15} {:<22} {}\n", name, report::plain_citations(eq), std::isfinite(v) ? fmt::format("{:.17g}", v) : "singular");
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
  fmt::print("  {:<15} {:<22} {}\n", "regime", "sign(omega'' h_tilde)", to_string(c.regime));
}

// One wavenumber of a model other than the resonant chain.
void print_model_text(const NlsCoefficients& c, const Model& m, std::size_t branch) {
  std::string parameters;
  const auto& d = m.definition();
  for (std::size_t i = 0; i < d.parameters.size(); ++i)
    parameters += fmt::format("{}{}={:.12g}", i ? ", " : "", d.parameters[i].name, m.inputs()[i]);
  fmt::print("model {}, {} branch, theta = {:.12g} ({})\n", d.name, d.branch_names[branch], c.theta, parameters);
  const auto row = [](const char* name, double v) {
    fmt::print("  {:<15} {}\n", name, std::isfinite(v) ? fmt::format("{:.17g}", v) : "singular");
  };
  row("omega", c.omega);
  row("group_velocity", c.group_velocity);
  row("curvature", c.curvature);
  row("gamma", c.gamma);
  row("beta", c.beta);
  row("h", c.h);
  if (d.mean_flow) row("lambda", c.lambda);
  else fmt::print("  {:<15} {}\n", "lambda", "none (on-site model: no mean flow)");
  row("h_tilde", c.h_tilde);
  row("nonresonance1", c.nonresonance1);
  if (d.mean_flow) row("nonresonance2", c.nonresonance2);
  fmt::print("  {:<15} {}\n", "regime", to_string(c.regime));
}

// The wavenumbers of the --table rows, with their labels.
const std::vector<std::pair<const char*, double>>& table_thetas() {
  static const std::vector<std::pair<const char*, double>> thetas = {
      {"pi/8", std::numbers::pi / 8},      {"pi/4", std::numbers::pi / 4},      {"pi/2", std::numbers::pi / 2},
      {"3pi/5", 3 * std::numbers::pi / 5}, {"3pi/4", 3 * std::numbers::pi / 4}, {"pi", std::numbers::pi}};
  return thetas;
}

// One branch of the --table output: its coefficients at table_thetas().
struct TableBranch {
  std::string name;
  bool mean_flow = true;  // false: on-site model, no lambda
  std::vector<NlsCoefficients> rows;
};

// The table of the resonant chain at `p`: optical, then acoustic (the specialised evaluators).
std::vector<TableBranch> resonant_chain_table(const Params& p) {
  std::vector<TableBranch> table;
  for (Branch b : {Branch::optical, Branch::acoustic}) {
    table.push_back({std::string(to_string(b)), true, {}});
    for (const auto& [label, theta] : table_thetas()) table.back().rows.push_back(coefficients(p, b, theta));
  }
  return table;
}

// The table of every branch of a model, the highest first.
std::vector<TableBranch> model_table(const Model& m) {
  const auto& d = m.definition();
  std::vector<TableBranch> table;
  for (std::size_t b = d.branch_names.size(); b-- > 0;) {
    table.push_back({d.branch_names[b], d.mean_flow, {}});
    for (const auto& [label, theta] : table_thetas()) table.back().rows.push_back(coefficients(m, b, theta));
  }
  return table;
}

// --table as text: `title`, then per branch one aligned row per wavenumber.
void print_table(const std::string& title, const std::vector<TableBranch>& table) {
  fmt::print("{}\n", title);
  for (const TableBranch& branch : table) {
    fmt::print("\n{} branch\n{:>7} {:>12} {:>12} {:>12} {:>12} {:>12} {:>12} {:>12}  {}\n", branch.name, "theta",
               "omega", "c", "omega''", "beta", "h", "lambda", "h_tilde", "regime");
    for (std::size_t i = 0; i < branch.rows.size(); ++i) {
      const NlsCoefficients& c = branch.rows[i];
      fmt::print("{:>7}{}{}{}{}{}{}{}  {}\n", table_thetas()[i].first, cell(c.omega), cell(c.group_velocity),
                 cell(c.curvature), cell(c.beta), cell(c.h), branch.mean_flow ? cell(c.lambda) : fmt::format(" {:>12}", "none"),
                 cell(c.h_tilde), to_string(c.regime));
    }
  }
}

// --table --json: {"model", "branches": [{"branch", "rows": [coefficients with "theta_label"]}], "provenance"}
// on one line; lambda is null for an on-site model.
void print_table_json(const Model& model, const std::vector<TableBranch>& table) {
  nlohmann::json branches = nlohmann::json::array();
  for (const TableBranch& branch : table) {
    nlohmann::json rows = nlohmann::json::array();
    for (std::size_t i = 0; i < branch.rows.size(); ++i) {
      nlohmann::json row = to_json(branch.rows[i]);
      row["theta_label"] = table_thetas()[i].first;
      if (!branch.mean_flow) row["lambda"] = nullptr;
      rows.push_back(row);
    }
    branches.push_back({{"branch", branch.name}, {"rows", rows}});
  }
  const nlohmann::json j{{"model", model_json(model)}, {"branches", branches}, {"provenance", provenance_json()}};
  std::printf("%s\n", j.dump().c_str());
}

}  // namespace

void register_coeffs(CLI::App& app) {
  auto opts = std::make_shared<CoeffsOptions>();
  auto* cmd = app.add_subcommand(
      "coeffs",
      "NLS coefficients of the modulation equations (Sec. 3): omega, group velocity c, curvature omega'',\n"
      "gamma, beta, h, lambda, h_tilde = h - lambda beta, the two non-resonance values and the regime\n"
      "(focusing if omega'' h_tilde < 0). Dimensionless units of Sec. 2.");
  add_number(*cmd, "--theta", opts->theta, "carrier wavenumber in (-pi, pi], e.g. pi/2 (required unless --table; no default)");
  add_model_options(*cmd, opts->params, /*rho_required=*/false);
  add_model_file_options(*cmd, opts->model);
  cmd->add_option("--branch", opts->branch,
                  "dispersion branch: optical (omega_+) or acoustic (omega_-); other models: the names `lrchain "
                  "derive` lists (acoustic/optical or branch0, branch1, ...) (required unless --table; no default)")
      ->type_name("NAME");
  cmd->add_flag("--json", opts->json,
                "print one JSON object on one line instead of the text: theta, branch, the coefficients (singular "
                "ones as null), the model with its parameter values, provenance; with --table every branch's rows");
  cmd->add_flag("--table", opts->table, "print the table of every branch at theta = pi/8 ... pi instead");
  add_examples(*cmd, {"lrchain coeffs --branch optical --theta pi/2 --rho 1/3",
                      "lrchain coeffs --branch acoustic --theta 3*pi/5 --rho 1 --json",
                      "lrchain coeffs --table --rho 10", "lrchain coeffs --table --json"});
  cmd->callback([opts, cmd] {
    if (opts->table)  // the table has its own wavenumbers and every branch
      for (const char* name : {"--theta", "--branch"})
        if (cmd->count(name) > 0)
          throw InputError(std::string(name) + " is not used with --table (it lists every branch at theta = pi/8 ... pi)");
    if (opts->model.file.empty()) validate(opts->params);  // the resonant chain's own messages
    const Model model = load_selected_model(opts->model, *cmd, opts->params);
    const bool resonant_chain = model.name() == "resonant_chain";
    if (resonant_chain)  // the specialised evaluators (and the paper's text) for the resonant chain
      opts->params = Params{model.parameter("alpha"), model.parameter("delta0"), model.parameter("kappa"), model.parameter("rho")};
    if (opts->table) {
      if (resonant_chain) validate(opts->params);
      const std::vector<TableBranch> table = resonant_chain ? resonant_chain_table(opts->params) : model_table(model);
      if (opts->json) print_table_json(model, table);
      else if (resonant_chain)
        print_table(fmt::format("NLS coefficients, alpha={:g}, delta0={:.6g}, kappa={:g}, rho={:.6g} (derived by "
                                "lrchain-derive)", opts->params.alpha, opts->params.delta0, opts->params.kappa,
                                opts->params.rho), table);
      else
        print_table("NLS coefficients of model " + model.name(), table);
      return;
    }
    if (std::isnan(opts->theta)) throw InvalidParameter("theta", "is required: a wavenumber in (-pi, pi]");
    if (opts->branch.empty()) throw InvalidParameter("branch", "is required: 'optical' or 'acoustic' (or the model's branch names)");
    if (resonant_chain) {
      const Branch b = parse_branch(opts->branch);
      const NlsCoefficients c = coefficients(opts->params, b, opts->theta);
      if (opts->json) {
        nlohmann::json j = to_json(c);
        j["branch"] = std::string(to_string(b));
        j["model"] = model_json(model);
        j["provenance"] = provenance_json();
        std::printf("%s\n", j.dump().c_str());
      } else {
        print_text(c, b, opts->params);
      }
      return;
    }
    const Index branch = model.branch(opts->branch);
    const NlsCoefficients c = coefficients(model, branch, opts->theta);
    if (opts->json) {
      nlohmann::json j = to_json(c);
      j["branch"] = model.definition().branch_names[static_cast<std::size_t>(branch)];
      j["model"] = model_json(model);
      j["provenance"] = provenance_json();
      std::printf("%s\n", j.dump().c_str());
    } else {
      print_model_text(c, model, branch);
    }
  });
}

}  // namespace lrchain::cli
