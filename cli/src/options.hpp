#pragma once
// Shared option helpers for all subcommands: numeric options go through the one parser
// (lrchain/numeric_parse.hpp), so "1/3", "4/9", "pi/2", "3*pi/5" work everywhere.
#include <CLI/CLI.hpp>
#include <string>

#include "lrchain/numeric_parse.hpp"
#include "lrchain/params.hpp"

namespace lrchain::cli {

// Adds --name that accepts decimals, fractions and multiples of pi into `target`.
inline CLI::Option* add_number(CLI::App& app, const std::string& name, double& target,
                               const std::string& description) {
  const std::string param = name.substr(name.find_first_not_of('-'));
  auto* opt = app.add_option_function<std::string>(
      name, [&target, param](const std::string& text) { target = parse_number(text, param); },
      description);
  opt->type_name("NUM");
  return opt;
}

// The model parameters every subcommand shares: --rho, --kappa, --delta0, --alpha.
// Defaults are the paper's (alpha=3/2, delta0=4/9, kappa=1, rho=1/3).
inline void add_model_options(CLI::App& app, Params& p, bool rho_required) {
  auto* r = add_number(app, "--rho", p.rho, "mass ratio m2/m1 > 0 (default 1/3)");
  if (rho_required) r->required();
  add_number(app, "--kappa", p.kappa, "resonator spring constant > 0, dimensionless (default 1)");
  add_number(app, "--delta0", p.delta0, "precompression overlap > 0, dimensionless (default 4/9)");
  add_number(app, "--alpha", p.alpha, "Hertz exponent > 1 (default 3/2)");
}

}  // namespace lrchain::cli
