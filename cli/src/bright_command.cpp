// `lrchain bright solve|floquet|continue|evolve`: exact bright breathers of any model file (the paper's chain by
// default), the job of lrchain/jobs/bright_breather_job.hpp on the command line: options ->
// BrightBreatherConfig, the result -> JSON on stdout and the exit code; Newton progress on stderr,
// files in --out.
#include <CLI/CLI.hpp>
#include <cstdio>
#include <fmt/format.h>
#include <memory>
#include <nlohmann/json.hpp>

#include "commands.hpp"
#include "figure_format_option.hpp"
#include "help_text.hpp"
#include "lrchain/config/option_caps.hpp"
#include "lrchain/errors.hpp"
#include "lrchain/jobs/bright_breather_job.hpp"
#include "lrchain/jobs/bright_breather_schema.hpp"
#include "lattice_job.hpp"
#include "model_option.hpp"
#include "options.hpp"
#include "solver_options.hpp"

namespace lrchain::cli {

namespace {
using namespace lrchain::jobs::bright_breather;

struct BrightArgs {
  BrightBreatherConfig config;
  Params chain;          // the resonant chain's --alpha/--delta0/--kappa/--rho (aliases of --set)
  ModelSelection model;  // --model FILE --set NAME=VALUE (empty: the resonant chain)
  bool json_out = false, quiet = false;
};

std::string bright_help(const std::string& key) { return help_text(bright_breather_option(key)); }

void add_common(CLI::App& sub, BrightArgs& a) {
  BrightBreatherConfig& c = a.config;
  add_model_options(sub, a.chain, false);
  CLI::Option* omega_b = add_number(sub, "--omega-b", c.omega_b, bright_help("omega_b"));
  if (bright_breather_option("omega_b").required) omega_b->required();
  sub.add_option("--branch", c.branch, bright_help("branch"))->type_name("NAME");
  add_model_file_options(sub, a.model);
  sub.add_option("--center", c.center, bright_help("center"))
      ->check(CLI::IsMember({"site", "bond"}).description(""))
      ->type_name("site|bond");
  sub.add_option("--start", c.start, bright_help("start"))
      ->check(CLI::IsMember({"nls", "anti-continuum"}).description(""))
      ->type_name("nls|anti-continuum");
  sub.add_option("--coupling", c.coupling, bright_help("coupling"))->type_name("NAME");
  add_integer(sub, "--sites", c.sites, config::dark_sites.least, config::dark_sites.most, bright_help("sites"));
  add_number(sub, "--tail-tolerance", c.tail_tolerance, bright_help("tail_tolerance"));
  add_solver_options(sub, c.krylov,
                     [](const std::string& key) -> const jobs::JobOption& { return bright_breather_option(key); });
  sub.add_flag("--json", a.json_out, "print the JSON summary on one line (default: indented)");
  sub.add_flag("--quiet", a.quiet, "no Newton progress on stderr (default: progress shown)");
  sub.add_option("--out", c.out, bright_help("out"))->type_name("DIR");
  sub.add_option("--format", c.format, bright_help("format"))
      ->check(CLI::IsMember({"csv", "hdf5"}).description(""))
      ->type_name("csv|hdf5");
  add_max_memory(sub, c.max_memory);
  add_figure_format(sub);
}

// Validates, runs and reports one job: JSON on stdout, then exit 3 when Newton did not converge or
// its zero is no localized bright breather; files in --out.
void run_job(const BrightArgs& a, BrightStep step, const CLI::App& cmd) {
  refuse_without_out(cmd, a.config.out, {"--format", "--figure-format"});
  BrightBreatherConfig config = a.config;
  config.step = step;
  const Model model = load_selected_model(a.model, cmd, a.chain, true);
  const LatticeCode code = validated_lattice_job(config, model, a.model, bright_breather_options());
  BrightBreatherHooks hooks;
  if (!a.quiet)
    hooks.newton_progress = [](const sim::dark::NewtonRecord& r) {
      fmt::print(stderr, "newton {:2d}  max|F| = {:.3e}  max|step| = {:.3e}\n", r.iteration, r.residual, r.step);
    };
  if (!a.quiet)
    hooks.on_point = [count = 0](const sim::dark::BranchPoint& b) mutable {
      fmt::print(stderr, "point {:3d} omega_b = {:.6f} residual = {:.3e}\n", count++, b.omega_b, b.residual);
    };
  const BrightBreatherResult r = run(config, hooks);
  const nlohmann::json j = config.out.empty() ? to_json(r) : write(r, config.out);
  std::printf("%s\n", j.dump(a.json_out ? -1 : 2).c_str());
  std::fflush(stdout);
  if (const auto message = failure(r)) throw NumericalFailure(*message);
}

}  // namespace

void register_bright(CLI::App& app) {
  auto* bright = app.add_subcommand(
      "bright", "Exact bright breathers of any lattice (docs/bright-breathers.md): shooting Newton on the "
                "period-T_b map from the NLS seed at a focusing band edge, continuation in omega_b, Floquet stability");
  bright->require_subcommand(1);
  add_examples(*bright, {"lrchain bright solve --model klein_gordon --omega-b 1.19 --sites 81",
                         "lrchain bright floquet --model fput --center bond --omega-b 2.05 --sites 61 --out out/bright"});
  auto args = std::make_shared<BrightArgs>();
  auto* solve_cmd = bright->add_subcommand("solve", "Newton solve from the NLS bright-breather seed, checked to be localized");
  add_common(*solve_cmd, *args);
  add_examples(*solve_cmd, {"lrchain bright solve --model klein_gordon --omega-b 1.19 --sites 81",
                            "lrchain bright solve --model klein_gordon --set C=0.05 --omega-b 1.5 --start anti-continuum --sites 21"});
  solve_cmd->callback([args, solve_cmd] { run_job(*args, BrightStep::solve, *solve_cmd); });
  auto* floq = bright->add_subcommand(
      "floquet", "Solve, then the Floquet multipliers of the monodromy matrix, the trivial +1 ones removed");
  add_common(*floq, *args);
  add_number(*floq, "--unit-tolerance", args->config.unit_tolerance, bright_help("unit_tolerance"));
  add_examples(*floq, {"lrchain bright floquet --model fput --center bond --omega-b 2.05 --sites 61 --out out/bright"});
  floq->callback([args, floq] { run_job(*args, BrightStep::floquet, *floq); });
  auto* cont = bright->add_subcommand(
      "continue", "Solve, then pseudo-arclength continuation in omega_b away from the band edge, Floquet at every point");
  add_common(*cont, *args);
  add_number(*cont, "--unit-tolerance", args->config.unit_tolerance, bright_help("unit_tolerance"));
  add_integer(*cont, "--points", args->config.points, config::dark_points.least, config::dark_points.most, bright_help("points"));
  add_number(*cont, "--ds", args->config.ds, bright_help("ds"));
  add_number(*cont, "--locate-tolerance", args->config.locate_tolerance, bright_help("locate_tolerance"));
  cont->add_option("--parameter", args->config.parameter, bright_help("parameter"))->type_name("NAME");
  cont->add_option_function<std::string>(
          "--to", [args](const std::string& text) { args->config.to = parse_number(text, "to"); }, bright_help("to"))
      ->type_name("NUM");
  add_examples(*cont, {"lrchain bright continue --model klein_gordon --omega-b 1.19 --sites 61 --points 10 --out out/bright-branch",
                       "lrchain bright continue --model klein_gordon --set a=0 --omega-b 1.1 --sites 21 --parameter C --to 0.001"});
  cont->callback([args, cont] { run_job(*args, BrightStep::branch, *cont); });
  auto* evo = bright->add_subcommand(
      "evolve", "Solve, then integrate the breather over --periods periods: profile and energy drift, or the growth "
                "rate of a perturbation against the largest Floquet multiplier's");
  add_common(*evo, *args);
  add_number(*evo, "--unit-tolerance", args->config.unit_tolerance, bright_help("unit_tolerance"));
  add_integer(*evo, "--periods", args->config.periods, 1, 1'000'000, bright_help("periods"));
  evo->add_option("--perturb", args->config.perturb, bright_help("perturb"))
      ->check(CLI::IsMember({"none", "unstable", "random"}).description(""))
      ->type_name("KIND");
  add_number(*evo, "--perturb-size", args->config.perturb_size, bright_help("perturb_size"));
  evo->add_option("--seed", args->config.seed, bright_help("seed"))->type_name("N");
  add_examples(*evo, {"lrchain bright evolve --model fput --set a=0 --center site --omega-b 2.2 --sites 41 --periods 40 "
                      "--perturb unstable --out out/bright-evolve"});
  evo->callback([args, evo] { run_job(*args, BrightStep::evolve, *evo); });
}

}  // namespace lrchain::cli
