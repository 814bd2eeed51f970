// `lrchain dark solve|continue|floquet|evolve`: exact stationary dark breathers (Sec. 5.3-5.4,
// Figs. 17-25), the dark job of lrchain/jobs/dark_job.hpp on the command line: options -> DarkConfig,
// the result -> JSON on stdout and the exit code; Newton and branch progress on stderr, files in --out.
#include <CLI/CLI.hpp>
#include <algorithm>
#include <cstdio>
#include <fmt/format.h>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>

#include "commands.hpp"
#include "figure_format_option.hpp"
#include "help_text.hpp"
#include "lrchain/config/option_caps.hpp"
#include "lrchain/errors.hpp"
#include "lrchain/jobs/dark_job.hpp"
#include "lrchain/jobs/dark_schema.hpp"
#include "model_option.hpp"
#include "options.hpp"
#include "solver_options.hpp"
#include "stop_signals.hpp"

namespace lrchain::cli {

namespace {
using namespace lrchain::jobs::dark;

struct DarkArgs {
  DarkConfig config;
  ModelSelection model;  // --model FILE --set NAME=VALUE (empty: the resonant chain through Params)
  bool json_out = false, quiet = false;
};

// The job's refusal with the command's spelling of the key, also in its advice: omega_b -> omega-b,
// "raise omega_b" -> "raise omega-b" (the symbol omega_b in a formula stays).
InvalidParameter option_spelling(const InvalidParameter& e) {
  const std::string key = e.parameter();
  std::string option = key;
  std::replace(option.begin(), option.end(), '_', '-');
  const std::string what = e.what(), prefix = "invalid " + key + ": ";
  std::string text = what.rfind(prefix, 0) == 0 ? what.substr(prefix.size()) : what;
  for (const std::string verb : {"raise ", "lower "})
    for (auto at = text.find(verb + key); at != std::string::npos; at = text.find(verb + key, at + 1))
      text.replace(at + verb.size(), key.size(), option);
  return InvalidParameter(option, text);
}

// An option's help and whether it is required, from the job's schema (dark_schema.hpp).
std::string help(const std::string& key) { return help_text(dark_option(key)); }
CLI::Option* from_schema(CLI::Option* option, const std::string& key) {
  return dark_option(key).required ? option->required() : option;
}

void add_common(CLI::App& sub, DarkArgs& a) {
  DarkConfig& c = a.config;
  add_model_options(sub, c.params, false);
  from_schema(add_number(sub, "--omega-b", c.omega_b, help("omega_b")), "omega_b");
  sub.add_option("--branch", c.branch, help("branch"))->type_name("NAME");
  add_model_file_options(sub, a.model);
  sub.get_option("--set")->description("model parameter, repeatable: --set w0=2 --set b=-1/2 (default: the model "
                                       "file's defaults; with --model only)");
  sub.add_option("--center", c.center, help("center"))
      ->check(CLI::IsMember({"bond", "site"}).description(""))
      ->type_name("bond|site");
  add_integer(sub, "--sites", c.sites, config::dark_sites.least, config::dark_sites.most, help("sites"));
  add_solver_options(sub, c.krylov, [](const std::string& key) -> const jobs::JobOption& { return dark_option(key); });
  if (sub.get_name() == "floquet")
    sub.add_option("--dark-floquet", c.krylov.dark_floquet, help("dark_floquet"))
        ->check(CLI::IsMember({"auto", "window", "arnoldi"}).description(""))
        ->type_name("METHOD");
  sub.add_option("--mode", c.mode, help("mode"))
      ->check(CLI::IsMember({"reversible", "full"}).description(""))
      ->type_name("reversible|full");
  sub.add_flag("--json", a.json_out, "print the JSON summary on one line (default: indented)");
  sub.add_flag("--quiet", a.quiet, "no Newton progress on stderr (default: progress shown)");
  sub.add_option("--out", c.out, help("out"))->type_name("DIR");
  add_max_memory(sub, c.max_memory);
  add_figure_format(sub);
}

// One line per Newton iteration and per branch point on stderr (unless --quiet).
DarkRunHooks progress_hooks(const DarkArgs& a) {
  DarkRunHooks hooks;
  hooks.stop = StopSignals::flag();  // SIGINT/SIGTERM: stop after the current branch point or period
  if (a.quiet) return hooks;
  hooks.newton_progress = [](const sim::dark::NewtonRecord& r) {
    fmt::print(stderr, "newton {:2d}  max|F| = {:.3e}  max|step| = {:.3e}\n", r.iteration, r.residual, r.step);
  };
  hooks.on_point = [count = 0](const sim::dark::BranchPoint& b) mutable {
    std::fprintf(stderr, "point %3d omega_b = %.6f norm^2 = %.5f %s max|lambda| = %.5f%s\n", count++, b.omega_b,
                 b.measures.norm_squared, b.floquet.kind().c_str(), b.floquet.max_modulus,
                 b.contact_changes_per_period ? fmt::format(" contact changes {}", *b.contact_changes_per_period).c_str()
                                              : "");
  };
  return hooks;
}

// Validates, runs and reports one dark job: JSON on stdout, then exit 3 (Newton or the corrector
// failed) or 130/143 (interrupted), files in --out.
void run_job(const DarkArgs& a, DarkConfig config) {
  try {
    validate(config);
  } catch (const InvalidParameter& e) {
    throw option_spelling(e);
  }
  std::optional<StopSignals> signals;  // a branch or an evolution stops at a point/period; a solve at once
  if (config.step == DarkStep::branch || config.step == DarkStep::evolve) signals.emplace();
  const DarkResult r = [&] {
    try {
      return run(config, progress_hooks(a));
    } catch (const InvalidParameter& e) {  // a refusal that needs the solution (perturb unstable on a stable breather)
      throw option_spelling(e);
    }
  }();
  if (config.step == DarkStep::evolve && r.newton.converged && r.evolution.periods.empty())
    throw Interrupted(StopSignals::received(), "interrupted before the first period");
  const nlohmann::json j = config.out.empty() ? to_json(r) : write(r, config.out);
  std::printf("%s\n", j.dump(a.json_out ? -1 : 2).c_str());
  std::fflush(stdout);
  const bool interrupted = config.step == DarkStep::branch ? r.branch.interrupted : StopSignals::received() != 0;
  if (r.newton.converged && interrupted) {
    if (config.step == DarkStep::branch)
      throw Interrupted(StopSignals::received(),
                        fmt::format("interrupted by {} after {} branch points{}",
                                    StopSignals::name(StopSignals::received()), r.branch.points.size(),
                                    config.out.empty() ? std::string() : "; the branch so far is in " + config.out));
    if (config.step == DarkStep::evolve)
      throw Interrupted(StopSignals::received(), fmt::format("interrupted after {} periods", r.evolution.periods.size()));
  }
  if (const auto message = failure(r)) throw NumericalFailure(*message);
}

// The resonant chain through Params, or (--model) any model file.
void dispatch(const DarkArgs& a, DarkStep step, const CLI::App& cmd) {
  refuse_without_out(cmd, a.config.out, {"--format", "--figure-format"});
  DarkConfig config = a.config;
  config.step = step;
  if (a.model.file.empty()) {
    if (!a.model.set.empty()) throw InputError("--set takes the parameters of a --model FILE; give --model");
    run_job(a, config);
    return;
  }
  if (config.full_monodromy) throw InputError("--full-monodromy: with --model the Floquet multipliers always come from the full-period monodromy");
  const Model model = load_selected_model(a.model, cmd, config.params, true);
  const LatticeCode code = lattice_kernels_for(a.model, model);
  config.model = &model;
  config.kernels = code.kernels.get();
  run_job(a, config);
}

}  // namespace

void register_dark(CLI::App& app) {
  auto* dark = app.add_subcommand(
      "dark", "Exact stationary dark breathers (Secs. 5.3-5.4): shooting Newton on the period-T_b map, "
              "continuation in omega_b, Floquet stability");
  dark->require_subcommand(1);
  add_examples(*dark, {"lrchain dark continue --rho 1/3 --branch optical --omega-b 2.42 --points 12 --out out/dark",
                       "lrchain dark solve --model klein_gordon --set b=-1/2 --omega-b 1.17 --sites 61"});
  auto args = std::make_shared<DarkArgs>();
  DarkConfig& c = args->config;
  auto* solve_cmd = dark->add_subcommand("solve", "Newton solve from the eq:xy_app seed");
  add_common(*solve_cmd, *args);
  add_examples(*solve_cmd, {"lrchain dark solve --rho 1/3 --branch optical --center bond --omega-b 2.44 --out out/dark-solve",
                            "lrchain dark solve --model klein_gordon --set b=-1/2 --omega-b 1.17 --sites 61"});
  solve_cmd->callback([args, solve_cmd] { dispatch(*args, DarkStep::solve, *solve_cmd); });
  auto* floq = dark->add_subcommand("floquet", "Solve, then the Floquet multipliers of the monodromy matrix (Sec. 5.4)");
  add_common(*floq, *args);
  floq->add_flag("--full-monodromy", c.full_monodromy, help("full_monodromy"));
  add_examples(*floq, {"lrchain dark floquet --rho 1/3 --center bond --omega-b 2.44 --sites 51",
                       "lrchain dark floquet --model diatomic_chain --omega-b 1.33 --sites 41"});
  floq->callback([args, floq] { dispatch(*args, DarkStep::floquet, *floq); });
  auto* cont = dark->add_subcommand(
      "continue", "Pseudo-arclength continuation in omega_b through turning points, Floquet at every point");
  add_common(*cont, *args);
  add_integer(*cont, "--points", c.points, config::dark_points.least, config::dark_points.most, help("points"));
  add_number(*cont, "--ds", c.ds, help("ds"));
  add_number(*cont, "--omega-min", c.omega_min, help("omega_min"));
  add_number(*cont, "--omega-max", c.omega_max, help("omega_max"));
  cont->add_option("--parameter", c.parameter, help("parameter"))->type_name("NAME");
  cont->add_option_function<std::string>(
          "--to", [&c](const std::string& text) { c.to = parse_number(text, "to"); }, help("to"))
      ->type_name("NUM");
  add_examples(*cont, {"lrchain dark continue --rho 1/3 --branch optical --center bond --omega-b 2.44 --points 10 --out out/dark"});
  cont->callback([args, cont] { dispatch(*args, DarkStep::branch, *cont); });
  auto* evo = dark->add_subcommand(
      "evolve", "Solve, then integrate eq:Hertzd0S from the solution: space-time x_n, y_n, E_b(t), breather position (Figs. 21, 22, 25)");
  add_common(*evo, *args);
  from_schema(add_number(*evo, "--t-end", c.t_end, help("t_end")), "t_end");
  add_integer(*evo, "--samples", c.samples, config::dark_samples.least, config::dark_samples.most, help("samples"));
  evo->add_option("--perturb", c.perturb, help("perturb"))
      ->check(CLI::IsMember({"none", "unstable", "random"}).description(""))
      ->type_name("KIND");
  add_number(*evo, "--perturb-size", c.perturb_size, help("perturb_size"));
  evo->add_option("--seed", c.seed, help("seed"))->type_name("N");
  add_examples(*evo, {"lrchain dark evolve --rho 1/3 --center bond --omega-b 2.44 --t-end 500 --out out/dark-evolve"});
  evo->callback([args, evo] { dispatch(*args, DarkStep::evolve, *evo); });
  for (auto* sub : {solve_cmd, floq, cont, evo})
    sub->add_option("--format", c.format, help("format"))
        ->check(CLI::IsMember({"csv", "hdf5"}).description(""))
        ->type_name("csv|hdf5");
}

}  // namespace lrchain::cli
