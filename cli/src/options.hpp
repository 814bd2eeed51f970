#pragma once
// Shared option helpers for all subcommands: numeric options go through the one parser
// (lrchain/numeric_parse.hpp), so "1/3", "4/9", "pi/2", "3*pi/5" work everywhere.
#include <CLI/CLI.hpp>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <limits>
#include <string>
#include <utility>
#include <vector>

#include "lrchain/checked_number.hpp"
#include "lrchain/errors.hpp"
#include "lrchain/numeric_parse.hpp"
#include "lrchain/params.hpp"
#include "lrchain/sim/resource_estimate.hpp"

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

// Adds --name taking one or more numbers, each parsed like add_number, into `target` (replacing
// its default), e.g. --snapshots 0 pi 2e3.
inline CLI::Option* add_number_list(CLI::App& app, const std::string& name, std::vector<double>& target,
                                    const std::string& description) {
  const std::string param = name.substr(name.find_first_not_of('-'));
  auto* opt = app.add_option_function<std::vector<std::string>>(
      name,
      [&target, param](const std::vector<std::string>& texts) {
        target.clear();
        for (const auto& text : texts) target.push_back(parse_number(text, param));
      },
      description);
  opt->type_name("NUM");
  return opt;
}

// The integer written in `text` (any number syntax: 1e3, 2*500) for --param in [min, max]
// (lrchain::checked_integer). Where `max` only guards against overflow (at least 2^31 - 1) a
// refusal states the lower bound alone: "must be an integer >= 5".
inline std::int64_t option_integer(const std::string& text, const std::string& param, std::int64_t min,
                                   std::int64_t max) {
  const double v = parse_number(text, param);
  if (max >= std::numeric_limits<std::int32_t>::max() && !(std::isfinite(v) && v == std::floor(v) && v >= double(min)))
    throw InvalidParameter(param, "must be an integer >= " + std::to_string(min));
  return checked_integer(v, param, min, max);
}

// Adds --name taking an integer in [min, max] into `target` (option_integer): integral values
// written as numbers, e.g. 1e3, are accepted, fractions, NaN, inf and overflow are not.
template <class Int>
CLI::Option* add_integer(CLI::App& app, const std::string& name, Int& target, std::int64_t min,
                         std::int64_t max, const std::string& description) {
  const std::string param = name.substr(name.find_first_not_of('-'));
  auto* opt = app.add_option_function<std::string>(
      name, [&target, param, min, max](const std::string& text) { target = static_cast<Int>(option_integer(text, param, min, max)); },
      description);
  opt->type_name("INT");
  return opt;
}

// Adds --max-memory SIZE (2G, 500M, ...) into `bytes`: the memory a job may use before it is
// refused (default 0: the machine's available memory).
inline CLI::Option* add_max_memory(CLI::App& app, double& bytes) {
  auto* opt = app.add_option_function<std::string>(
      "--max-memory", [&bytes](const std::string& text) { bytes = sim::parse_memory_size(text, "max-memory"); },
      "refuse the job when its estimated memory exceeds SIZE, e.g. 2G or 500M (default: the memory "
      "this machine has available)");
  opt->type_name("SIZE");
  return opt;
}

// The option --name as given to `cmd` or, before the subcommand, to a command above it (`simulate
// --out DIR bright` and `simulate bright --out DIR` are the same run); nullptr when not given.
inline const CLI::Option* given_option(const CLI::App& cmd, const std::string& name) {
  for (const CLI::App* at = &cmd; at != nullptr; at = at->get_parent())
    if (const CLI::Option* option = at->get_option_no_throw(name); option != nullptr && option->count() > 0)
      return option;
  return nullptr;
}

// Refuses (exit 2) the options among `names` that only shape the files written to --out when the
// run writes no files (`out` empty): given alone they would do nothing.
inline void refuse_without_out(const CLI::App& cmd, const std::string& out, std::initializer_list<const char*> names) {
  if (!out.empty()) return;
  for (const char* name : names)
    if (given_option(cmd, name) != nullptr)
      throw InputError(std::string(name) + " needs --out DIR: it only changes the files written there");
}

// A default value as the help shows it: the paper's fractions as fractions, else %g.
inline std::string default_text(double v) {
  for (const auto& [num, den] : {std::pair{1, 3}, std::pair{4, 9}, std::pair{3, 2}, std::pair{2, 3}})
    if (std::abs(v - static_cast<double>(num) / den) < 1e-14) return std::to_string(num) + "/" + std::to_string(den);
  char buf[32];
  std::snprintf(buf, sizeof buf, "%g", v);
  return buf;
}

// Adds --name for the physical parameter `range` (lrchain/params.hpp): parsed like add_number and
// refused at once when outside its range. The help shows the range and `default_note`.
inline CLI::Option* add_parameter(CLI::App& app, const std::string& name, double& target, const PhysicalRange& range,
                                  const std::string& default_note) {
  const std::string param = name.substr(name.find_first_not_of('-'));
  auto* opt = app.add_option_function<std::string>(
      name,
      [&target, param, range](const std::string& text) {
        const double v = parse_number(text, param);
        check_in_range(v, range, param);
        target = v;
      },
      std::string(range.meaning) + ", in " + range.interval() + " (" + default_note + ")");
  opt->type_name("NUM");
  return opt;
}

// The model parameters every subcommand shares: --rho, --kappa, --delta0, --alpha, each refused
// outside its range (lrchain/params.hpp). The help shows the values in `p` at registration as the
// defaults (the paper's: alpha=3/2, delta0=4/9, kappa=1, rho=1/3, unless the subcommand's
// experiment uses others), so set them before calling this. The help lists them under their own
// heading, apart from the options every model takes.
inline void add_model_options(CLI::App& app, Params& p, bool rho_required) {
  const std::string group = "The paper's resonant chain";
  auto* r = add_parameter(app, "--rho", p.rho, rho_range, rho_required ? "required" : "default " + default_text(p.rho));
  if (rho_required) r->required();
  r->group(group);
  add_parameter(app, "--kappa", p.kappa, kappa_range, "default " + default_text(p.kappa))->group(group);
  add_parameter(app, "--delta0", p.delta0, delta0_range, "default " + default_text(p.delta0))->group(group);
  add_parameter(app, "--alpha", p.alpha, alpha_range, "default " + default_text(p.alpha))->group(group);
}

}  // namespace lrchain::cli
