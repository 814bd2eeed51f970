// `lrchain derive --model FILE`: a lattice model file through the multiple-scale engine — the
// derived NLS coefficients in symbolic form, the case (mean flow or on-site), the branches and the
// check report (docs/models.md). A failing check fails the command.
#include <fmt/format.h>

#include <csignal>
#include <cstdio>
#include <memory>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "commands.hpp"
#include "help_text.hpp"
#include "lrchain/derivation/derivation_stop.hpp"
#include "lrchain/derivation/model_derivation.hpp"
#include "lrchain/derivation/symbolic_lock.hpp"
#include "lrchain/errors.hpp"
#include "lrchain/provenance_json.hpp"
#include "shipped_data.hpp"
#include "stop_signals.hpp"

namespace lrchain::cli {

namespace {

struct DeriveOptions {
  std::string model;
  std::vector<std::string> set;
  bool json = false, latex = false;
};

std::string text(const GiNaC::ex& e, bool latex) {
  std::ostringstream os;
  if (latex) os << GiNaC::latex;
  os << e;
  return os.str();
}

// --set name=value pairs (value: number or fraction).
std::vector<std::pair<std::string, std::string>> overrides(const std::vector<std::string>& set) {
  std::vector<std::pair<std::string, std::string>> out;
  for (const auto& s : set) {
    const auto eq = s.find('=');
    if (eq == std::string::npos || eq == 0) throw InputError("--set " + s + ": expected name=value, e.g. --set rho=1/3");
    out.emplace_back(s.substr(0, eq), s.substr(eq + 1));
  }
  return out;
}

nlohmann::json to_json(const derivation::ModelDerivation& m, const derivation::Symbols& s, bool latex) {
  using nlohmann::json;
  json j;
  j["model"] = m.file.name;
  j["description"] = m.file.description;
  j["file"] = m.file.path;
  j["file_hash"] = {{"algorithm", "FNV-1a 64 of the file's bytes"}, {"value", derivation::hash_text(m.file.hash)}};
  json parameters = json::object();
  for (const auto& p : m.file.parameters) {
    const GiNaC::numeric v = GiNaC::ex_to<GiNaC::numeric>(m.values.at(p.symbol));
    parameters[p.name] = {{"value", v.to_double()}, {"exact", text(v, false)}, {"range", p.range.text}};
  }
  j["parameters"] = parameters;
  j["case"] = m.coefficients.mean_flow ? "mean_flow" : "on_site";
  json intermediates = json::object();
  for (const auto& i : m.file.intermediates) intermediates[i.name] = text(i.value, latex);
  j["intermediates"] = intermediates;
  json fields = json::array();
  for (const auto& f : m.file.model.fields) fields.push_back(f);
  j["fields"] = fields;
  json branches = json::array();
  for (const auto& b : m.branches)
    branches.push_back({{"name", b.name}, {"real", b.real}, {"omega_at_theta_0", b.omega_at_zero},
                        {"omega_at_theta_pi", b.omega_at_pi}, {"problem", b.problem.empty() ? json(nullptr) : json(b.problem)}});
  j["branches"] = branches;
  json coefficients = json::object();
  for (const auto& [name, e] : derivation::symbolic_coefficients(m, s)) coefficients[name] = text(e, latex);
  j["coefficients"] = coefficients;
  j["notation"] = latex ? "LaTeX" : "GiNaC plain text";
  json checks = json::array();
  for (const auto& c : m.checks)
    checks.push_back({{"name", c.name}, {"passed", c.passed}, {"method", c.method}, {"detail", c.detail}});
  j["checks"] = checks;
  j["passed"] = m.passed();
  j["derive_seconds"] = m.derive_seconds;
  j["check_seconds"] = m.check_seconds;
  j["provenance"] = provenance_json();
  return j;
}

}  // namespace

// derive_model polling SIGINT/SIGTERM between its steps: a signal ends it with exit 130/143 and
// one line (lrchain::Interrupted), nothing printed.
std::unique_ptr<derivation::ModelDerivation> derive_until_stopped(derivation::ModelFile file, const GiNaC::exmap& values,
                                                                  const derivation::Symbols& symbols) {
  const StopSignals signals;
  const derivation::DerivationStopScope scope(StopSignals::flag());
  const std::string path = file.path;
  try {
    return derivation::derive_model(std::move(file), values, symbols);
  } catch (const derivation::DerivationStopped&) {
    const int signal_number = StopSignals::received() != 0 ? StopSignals::received() : SIGINT;
    throw Interrupted(signal_number, std::string("interrupted by ") + StopSignals::name(signal_number) + " while deriving " + path);
  }
}

void register_derive(CLI::App& app) {
  auto opts = std::make_shared<DeriveOptions>();
  auto* cmd = app.add_subcommand(
      "derive",
      "Derive the NLS coefficients of a lattice model file (docs/models.md): the case (mean flow or on-site),\n"
      "the branches, c, gamma, omega'', beta, h, lambda, h_tilde in symbolic form, and the check report.\n"
      "Exit 1 when a check fails, 2 for a bad model file or parameter value.");
  cmd->add_option_function<std::string>(
         "--model", [opts](const std::string& text) { opts->model = resolve_model_argument(text); },
         "model file (TOML), or the name of a shipped model, e.g. klein_gordon")
      ->required()
      ->type_name("FILE");
  cmd->add_option("--set", opts->set, "parameter value, repeatable: --set rho=1/3 --set kappa=2 (default: the model file's "
                  "defaults)")->type_name("NAME=VALUE");
  cmd->add_flag("--json", opts->json, "print one JSON object on one line instead of the text report (default: text)");
  cmd->add_flag("--latex", opts->latex, "write expressions in LaTeX (default: plain text)");
  add_examples(*cmd, {"lrchain derive --model klein_gordon",
                      "lrchain derive --model fput --set a=1/4 --set b=1/2 --json"});
  cmd->callback([opts] {
    const std::lock_guard<std::recursive_mutex> lock(derivation::symbolic_engine_mutex());  // GiNaC: one thread at a time
    const derivation::Symbols symbols;
    derivation::ModelFile file = derivation::load_model_file(opts->model);
    const GiNaC::exmap values = derivation::parameter_values(file, overrides(opts->set));
    const auto m = derive_until_stopped(std::move(file), values, symbols);
    if (opts->json) std::printf("%s\n", to_json(*m, symbols, opts->latex).dump().c_str());
    else std::fputs(derivation::model_report(*m, symbols, opts->latex).c_str(), stdout);
    if (!m->passed()) throw std::runtime_error("model " + m->file.name + ": a derivation check failed (see the report)");
  });
}

}  // namespace lrchain::cli
