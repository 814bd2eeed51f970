// `lrchain simulate`: lattice runs of Sec. 4 (bright breathers vs the NLS ansatz), from options or
// from one TOML config (examples/*.toml). JSON summary on stdout; data and figures in --out.
#include <signal.h>
#include <unistd.h>

#include <atomic>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <memory>
#include <string>

#include <nlohmann/json.hpp>

#include "commands.hpp"
#include "lrchain/errors.hpp"
#include "lrchain/sim/bright_outputs.hpp"
#include "lrchain/sim/bright_run.hpp"
#include "lrchain/sim/experiment_config.hpp"
#include "options.hpp"

namespace lrchain::cli {

namespace {

std::atomic<bool> g_stop{false};

extern "C" void on_sigint(int) {
  g_stop.store(true);
  ::signal(SIGINT, SIG_DFL);  // a second Ctrl-C ends the process at once
}

// Progress bar on stderr, only when stderr is a terminal and the run lasts more than ~2 s.
struct ProgressBar {
  bool enabled = ::isatty(STDERR_FILENO) != 0;
  std::chrono::steady_clock::time_point start = std::chrono::steady_clock::now(), last = start;
  bool drawn = false;
  void update(double f) {
    if (!enabled) return;
    const auto now = std::chrono::steady_clock::now();
    if (now - start < std::chrono::seconds(2) || now - last < std::chrono::milliseconds(250)) return;
    last = now;
    const int width = 40, filled = int(f * width + 0.5);
    std::fprintf(stderr, "\r[%s%s] %5.1f%%", std::string(filled, '#').c_str(),
                 std::string(width - filled, ' ').c_str(), 100.0 * f);
    std::fflush(stderr);
    drawn = true;
  }
  ~ProgressBar() {
    if (drawn) std::fprintf(stderr, "\r%60s\r", "");
  }
};

sim::RunControl make_control(ProgressBar& bar) {
  g_stop.store(false);
  ::signal(SIGINT, on_sigint);
  sim::RunControl c;
  c.stop = &g_stop;
  c.progress = [&bar](double f) { bar.update(f); };
  return c;
}

void run_bright_and_report(const sim::BrightRunConfig& cfg, const std::string& out, bool compact) {
  const auto wall0 = std::chrono::steady_clock::now();
  ProgressBar bar;
  sim::BrightRunResult r;
  {
    const sim::RunControl control = make_control(bar);
    r = sim::run_bright(cfg, control);
  }
  ::signal(SIGINT, SIG_DFL);
  nlohmann::json j = sim::to_json(cfg, r.summary);
  if (!out.empty()) {
    j["out"] = out;
    j["figures"] = sim::write_bright_outputs(out, r, j);
  }
  j["wall_seconds"] = std::chrono::duration<double>(std::chrono::steady_clock::now() - wall0).count();
  std::cout << (compact ? j.dump() : j.dump(2)) << std::endl;
  if (r.summary.interrupted) std::exit(130);
  if (r.summary.blew_up) {
    std::fprintf(stderr, "lrchain: error: the integration blew up (non-finite state) at t = %g\n",
                 r.summary.t_end);
    std::exit(1);
  }
}

void add_integrator_options(CLI::App& app, sim::IntegratorOptions& o, std::string& stepper) {
  app.add_option("--stepper", stepper, "rkf78 (default), dopri5 or symplectic");
  add_number(app, "--abs-tol", o.abs_tol, "absolute local error tolerance (default 1e-12)");
  add_number(app, "--rel-tol", o.rel_tol, "relative local error tolerance (default 1e-12)");
  add_number(app, "--dt", o.dt, "initial step (adaptive) or fixed step (symplectic), default 0.05");
}

}  // namespace

void register_simulate(CLI::App& app) {
  auto* sim_cmd = app.add_subcommand(
      "simulate", "integrate the lattice (eq:Hertz / eq:Hertzd0S): bright breathers vs the NLS ansatz");
  auto config = std::make_shared<std::string>();
  auto out = std::make_shared<std::string>();
  auto compact = std::make_shared<bool>(false);
  sim_cmd->add_option("--config", *config, "run the experiment in this TOML file (examples/*.toml)");
  sim_cmd->add_option("--out", *out, "output directory for data and figures");
  sim_cmd->add_flag("--json", *compact, "print the JSON summary on one line");
  sim_cmd->require_subcommand(0, 1);

  // simulate bright
  auto cfg = std::make_shared<sim::BrightRunConfig>();
  auto stepper = std::make_shared<std::string>("rkf78");
  auto snapshots = std::make_shared<std::vector<double>>();
  auto* bright = sim_cmd->add_subcommand(
      "bright", "lattice run from the NLS bright breather (eq:focus_app, eq:focus_ini), Sec. 4");
  bright->add_option("--branch", [cfg](const std::vector<std::string>& v) {
    cfg->branch = parse_branch(v.at(0));
    return true;
  }, "optical or acoustic")->required()->type_name("B");
  add_number(*bright, "--theta", cfg->theta, "carrier wavenumber in (0, pi]")->required();
  add_model_options(*bright, cfg->params, true);
  bright->add_option_function<std::string>("--detuning", [cfg](const std::string& s) {
    cfg->detuning = parse_number(s, "detuning");
  }, "omega_b - omega (default sign(h_tilde)*1e-4)")->type_name("NUM");
  add_number(*bright, "--n0", cfg->n0, "initial breather centre (default 0)");
  bright->add_option("--N", cfg->N, "strain sites n = -N..N (default 500)");
  add_number(*bright, "--periods", cfg->periods, "run length in breather periods T_b (default 200)");
  add_number(*bright, "--sample-every", cfg->sample_every, "sampling interval in T_b (default 0.25)");
  add_number(*bright, "--spacetime-every", cfg->spacetime_every,
             "energy-density row interval in T_b (default 1)");
  add_number(*bright, "--error-window", cfg->error_window_end,
             "also report max E_x, E_y for t <= this time");
  bright->add_option("--snapshots", *snapshots, "snapshot times in T_b (default 0 50.125 200)");
  bright->add_flag("--ansatz-ends", cfg->ansatz_ends,
                   "end beads follow the ansatz (emitting boundary conditions, Sec. 4.2)");
  add_integrator_options(*bright, cfg->integrator, *stepper);
  bright->fallthrough();  // --out, --json may follow the subcommand
  bright->callback([=] {
    cfg->integrator.stepper = sim::parse_stepper(*stepper);
    if (!snapshots->empty()) cfg->snapshot_periods = *snapshots;
    run_bright_and_report(*cfg, *out, *compact);
  });

  sim_cmd->callback([=] {
    if (!sim_cmd->get_subcommands().empty()) return;
    if (config->empty())
      throw InvalidParameter("config", "give a subcommand (bright) or --config FILE.toml");
    const sim::ExperimentConfig ec = sim::load_experiment_config(*config);
    const std::string dir = !out->empty() ? *out : ec.out_dir;
    if (ec.experiment == "bright") run_bright_and_report(ec.bright, dir, *compact);
  });
}

}  // namespace lrchain::cli
