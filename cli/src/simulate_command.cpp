// `lrchain simulate`: lattice runs of Sec. 4 (bright breathers vs the NLS ansatz), from options or
// from one TOML config (examples/*.toml). JSON summary on stdout; data and figures in --out.
#include <signal.h>
#include <unistd.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <limits>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "commands.hpp"
#include "figure_format_option.hpp"
#include "lrchain/errors.hpp"
#include "lrchain/jobs/experiment_config.hpp"
#include "lrchain/jobs/more_experiment_config.hpp"
#include "lrchain/jobs/simulate/simulate_job.hpp"
#include "lrchain/jobs/simulate/simulate_schema.hpp"
#include "lrchain/sim/strain_sites.hpp"
#include "help_text.hpp"
#include "options.hpp"
#include "schema_help.hpp"
#include "simulate_model_commands.hpp"
#include "stop_signals.hpp"

namespace lrchain::cli {

namespace {

// One argument as a POSIX shell reads it back (single quotes when it has anything but
// [A-Za-z0-9_./=:+,-]), for the restart command shown to the user; nothing here is ever executed.
std::string shell_quoted(const std::string& a) {
  if (!a.empty() && a.find_first_not_of("ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz"
                                        "0123456789_./=:+-,") == std::string::npos)
    return a;
  std::string q = "'";
  for (char ch : a) q += ch == '\'' ? std::string("'\\''") : std::string(1, ch);
  return q + "'";
}

// This process's command line with `--restart FILE` (replacing any earlier one): the command that
// continues an interrupted run. Read from /proc/self/cmdline; empty where that is unavailable.
std::string restart_command(const std::string& checkpoint) {
  std::ifstream in("/proc/self/cmdline", std::ios::binary);
  std::vector<std::string> args;
  for (std::string a; std::getline(in, a, '\0');) args.push_back(a);
  if (args.empty()) return {};
  std::string cmd;
  for (std::size_t i = 0; i < args.size(); ++i) {
    if (args[i] == "--restart") { ++i; continue; }
    if (args[i].rfind("--restart=", 0) == 0) continue;
    cmd += (cmd.empty() ? "" : " ") + shell_quoted(args[i]);
  }
  return cmd + " --restart " + shell_quoted(checkpoint);
}

// After the outputs of a run stopped by a signal are written: exit 128 + signal (via
// lrchain::Interrupted) with one line saying where the run stopped and how to continue it.
void throw_if_interrupted(bool interrupted, double t_reached, double checkpoint_time,
                          const std::string& checkpoint_file) {
  if (!interrupted) return;
  const int signal_number = StopSignals::received() != 0 ? StopSignals::received() : SIGINT;
  const char* name = StopSignals::name(signal_number);
  if (checkpoint_file.empty() || checkpoint_time < 0)
    throw Interrupted(signal_number, fmt::format("interrupted by {} at t = {}; no checkpoint written "
                                                 "(give --out or --checkpoint to make a run restartable)",
                                                 name, t_reached));
  const std::string cmd = restart_command(checkpoint_file);
  throw Interrupted(signal_number,
                    fmt::format("interrupted by {} at t = {}; checkpoint at t = {} in '{}'; continue with: {}",
                                name, t_reached, checkpoint_time, checkpoint_file,
                                cmd.empty() ? "the same command with --restart " + checkpoint_file : cmd));
}

// Ends a run whose integration blew up (non-finite state): exit 3, after the outputs are written;
// the message says when and where (also in the JSON summary's "failure").
void throw_if_blew_up(const std::optional<sim::BlowUp>& blow_up, const std::string& out) {
  if (blow_up)
    throw NumericalFailure(blow_up->message() +
                           (out.empty() ? std::string() : "; the outputs up to then are in " + out));
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
  sim::RunControl c;
  c.stop = StopSignals::flag();
  c.progress = [&bar](double f) { bar.update(f); };
  return c;
}

// How a run reports: the JSON summary on one line (--json), and its files (--out, --no-figures, --format).
struct ReportStyle {
  bool compact_json = false;
  bool figures = true;
  std::string format = "csv";  // --format: csv (data files and figures) or hdf5 (result.h5)
};

// Runs one simulate job (jobs/simulate/simulate_job.hpp) with SIGINT/SIGTERM handling and a progress
// bar, prints its JSON summary, then ends like an interrupted run (130/143) or a blown-up one (3)
// where that applies.
template <class Config>
void run_and_report(const Config& cfg, const std::string& out, const ReportStyle& style) {
  const auto wall0 = std::chrono::steady_clock::now();
  StopSignals signals;
  ProgressBar bar;
  auto report = jobs::simulate(cfg, {out, style.figures, style.format}, make_control(bar));
  nlohmann::json& j = report.summary;
  j["wall_seconds"] = std::chrono::duration<double>(std::chrono::steady_clock::now() - wall0).count();
  std::cout << (style.compact_json ? j.dump() : j.dump(2)) << std::endl;
  std::fflush(stdout);
  const auto& s = report.result.summary;
  throw_if_interrupted(s.interrupted, s.t_end, s.last_checkpoint_time, report.checkpoint_file);
  throw_if_blew_up(s.blow_up, out);
}

// --sites of a bright run: the odd number 2N + 1 of strain sites n = -N..N, kept as given; the run
// takes its half-width N with its own range (sim::bright_sites, or sim::model_bright_sites with
// --model), so that an even or out-of-range count is refused (exit 2) with the range that applies.
void add_strain_sites(CLI::App& app, std::int64_t& sites) {
  auto* opt = app.add_option_function<std::string>(
      "--sites",
      [&sites](const std::string& text) {
        const double v = parse_number(text, "sites");
        if (!(std::isfinite(v) && v == std::floor(v) && std::abs(v) <= 9e18))
          throw InvalidParameter("sites", "must be an odd integer: the sites are n = -N..N, 2N + 1 of them");
        sites = static_cast<std::int64_t>(v);
      },
      schema_help(jobs::bright_options(), "sites"));
  opt->type_name("INT");
}

// --stepper, --abs-tol, --rel-tol, --dt (help from the job's schema); with o.automatic_dt the fixed-step steppers choose their
// step themselves unless --dt is given (the callback clears automatic_dt then).
void add_integrator_options(CLI::App& app, sim::IntegratorOptions& o, std::string& stepper,
                            const std::vector<jobs::JobOption>& schema) {
  app.add_option("--stepper", stepper, schema_help(schema, "stepper"))->type_name("NAME");
  add_number(app, "--abs-tol", o.abs_tol, schema_help(schema, "abs_tol"));
  add_number(app, "--rel-tol", o.rel_tol, schema_help(schema, "rel_tol"));
  add_number(app, "--dt", o.dt, schema_help(schema, "dt"));
}

// The storage of the options every `simulate` run shares; each command registers those it honours
// (add_output_options), and `simulate` all of them, so they may come before or after the subcommand.
struct SimulateOutputs {
  std::shared_ptr<std::string> out = std::make_shared<std::string>();
  std::shared_ptr<ReportStyle> style = std::make_shared<ReportStyle>();
  std::shared_ptr<std::string> restart = std::make_shared<std::string>();
  std::shared_ptr<std::string> checkpoint = std::make_shared<std::string>();
  std::shared_ptr<double> max_memory = std::make_shared<double>(0.0);
};

constexpr const char* subcommand_out =
    "output directory for data and figures (default: none, only the JSON summary is printed)";

// Adds --out (described by `out_help`), --json, --no-figures, --figure-format, --format to `cmd`;
// with `lattice_run` (the resonant chain's runs and --config) also --restart, --checkpoint and
// --max-memory. All write `o`.
void add_output_options(CLI::App& cmd, const SimulateOutputs& o, bool lattice_run, const std::string& out_help) {
  cmd.add_option("--out", *o.out, out_help)->type_name("DIR");
  cmd.add_flag("--json", o.style->compact_json, "print the JSON summary on one line (default: indented)");
  cmd.add_flag_callback("--no-figures", [style = o.style] { style->figures = false; },
                        "write the data and summary.json to --out but no figures (no gnuplot run; default: figures)");
  add_figure_format(cmd);
  cmd.add_option("--format", o.style->format,
                 "data files in --out: csv (CSV, float32 space-time files and figures; default) or hdf5 "
                 "(result.h5 with the series, fields, snapshots and summary; no figures)")
      ->check(CLI::IsMember({"csv", "hdf5"}).description(""))
      ->type_name("csv|hdf5");
  if (!lattice_run) return;
  cmd.add_option("--restart", *o.restart,
                 "continue the run from this checkpoint file (written with the same physics, lattice and stepper; "
                 "the outputs cover the whole run; default: none, a new run)")
      ->type_name("FILE");
  cmd.add_option("--checkpoint", *o.checkpoint,
                 "checkpoint file, written periodically, at the end and on SIGINT/SIGTERM (default OUT/checkpoint.bin: "
                 "on SIGINT/SIGTERM, and periodically with --checkpoint-every)")
      ->type_name("FILE");
  add_max_memory(cmd, *o.max_memory);
}

// A lattice run from its subcommand: its stepper, the run files and memory limit of the shared options,
// then run_and_report.
template <class Config>
void run_lattice_command(Config& c, const std::string& stepper, const SimulateOutputs& o) {
  c.integrator.stepper = sim::parse_stepper(stepper);
  c.restart_file = *o.restart;
  c.checkpoint_file = *o.checkpoint;
  c.max_memory = *o.max_memory;
  run_and_report(c, *o.out, *o.style);
}

// The outputs of a model-file run: views of `o`'s --out, --json, --no-figures and --format.
ModelRunOutput model_run_output(const SimulateOutputs& o) {
  return {o.out, std::shared_ptr<bool>(o.style, &o.style->compact_json), std::shared_ptr<bool>(o.style, &o.style->figures),
          std::shared_ptr<std::string>(o.style, &o.style->format)};
}

}  // namespace

void register_simulate(CLI::App& app) {
  auto* sim_cmd = app.add_subcommand(
      "simulate",
      "Integrate the lattice (eq:Hertz / eq:Hertzd0S) with Boost.Odeint: bright breathers against the NLS "
      "ansatz (Sec. 4.2), the boundary-driven chain (Sec. 4.3), the modulated wave (Sec. 5.1), or one "
      "experiment config (examples/*.toml). Times in the units of Sec. 2; data and figures go to --out.");
  auto config = std::make_shared<std::string>();
  sim_cmd->add_option("--config", *config,
                      "run the experiment in this TOML file (docs/configs.md, examples/*.toml; default: none, "
                      "give a subcommand instead)")->type_name("FILE");
  const SimulateOutputs outputs;
  const auto out = outputs.out;
  const auto style = outputs.style;
  const auto restart = outputs.restart;
  const auto checkpoint = outputs.checkpoint;
  const auto max_memory = outputs.max_memory;
  add_output_options(*sim_cmd, outputs, true,
                     "output directory for data and figures (default: a config's [output] dir)");
  sim_cmd->require_subcommand(0, 1);
  {
    // `simulate ring` (simulate_ring.cpp) reports through --out, --json, --no-figures, --figure-format and --format.
    register_simulate_ring(*sim_cmd, model_run_output(outputs));
    CLI::App& ring = *sim_cmd->get_subcommand("ring");
    add_output_options(ring, outputs, false, subcommand_out);
    add_examples(ring, {"lrchain simulate ring --model fput --branch acoustic --theta pi/2 --out out/ring-fput"});
  }
  add_examples(*sim_cmd, {"lrchain simulate --config examples/exp1_optical_pi2.toml --out out/exp1",
                          "lrchain simulate --config examples/models/fput_bright.toml --out out/fput"});

  // simulate bright
  auto cfg = std::make_shared<sim::BrightRunConfig>();
  auto stepper = std::make_shared<std::string>(sim::to_string(cfg->integrator.stepper));
  auto* bright = sim_cmd->add_subcommand(
      "bright", "Lattice run from the NLS bright breather (eq:focus_app, eq:focus_ini), Sec. 4.2");
  auto bright_branch = std::make_shared<std::string>();
  const auto& bright_schema = jobs::bright_options();
  const auto bright_help = [&bright_schema](const char* key) { return schema_help(bright_schema, key); };
  bright->add_option("--branch", *bright_branch, bright_help("branch"))->type_name("NAME");
  add_number(*bright, "--theta", cfg->theta, bright_help("theta"))->required();
  add_model_options(*bright, cfg->params, false);
  auto bright_model = std::make_shared<ModelSelection>();
  add_model_file_options(*bright, *bright_model);
  bright->add_option_function<std::string>("--detuning", [cfg](const std::string& s) {
    cfg->detuning = parse_number(s, "detuning");
  }, bright_help("detuning"))->type_name("NUM");
  add_number(*bright, "--n0", cfg->n0, bright_help("n0"));
  auto bright_sites = std::make_shared<std::int64_t>(sim::strain_site_count(cfg->N));
  add_strain_sites(*bright, *bright_sites);
  add_number(*bright, "--periods", cfg->periods, bright_help("periods"));
  add_number(*bright, "--sample-every", cfg->sample_every, bright_help("sample_every"));
  add_number(*bright, "--spacetime-every", cfg->spacetime_every, bright_help("spacetime_every"));
  add_number(*bright, "--error-window", cfg->error_window_end, bright_help("error_window_end"));
  add_number_list(*bright, "--snapshots", cfg->snapshot_periods, bright_help("snapshot_periods"));
  bright->add_flag("--ansatz-ends", cfg->ansatz_ends, bright_help("ansatz_ends"));
  add_number(*bright, "--checkpoint-every", cfg->checkpoint_every, bright_help("checkpoint_every"));
  add_integrator_options(*bright, cfg->integrator, *stepper, bright_schema);
  add_output_options(*bright, outputs, true, subcommand_out);
  add_examples(*bright, {"lrchain simulate bright --branch optical --theta pi/2 --rho 1/3 --sites 1001 --periods 200 --out out/exp1"});
  bright->callback([=] { with_option_names(jobs::bright_options(), [&] {
    if (!bright_model->file.empty()) {  // any model file: simulate_model_bright.cpp
      cfg->N = sim::strain_half_width(*bright_sites, sim::model_bright_sites);
      run_model_bright_command(*bright_model, *bright_branch, *cfg, *bright, model_run_output(outputs));
      return;
    }
    if (!bright_model->set.empty()) throw InputError("--set needs --model FILE (the resonant chain takes --rho, --kappa, ...)");
    refuse_ignored_options(*bright, *out, {}, "");
    cfg->N = sim::strain_half_width(*bright_sites, sim::bright_sites);
    cfg->branch = parse_branch(*bright_branch);
    if (bright->count("--dt") > 0) cfg->integrator.automatic_dt = false;
    run_lattice_command(*cfg, *stepper, outputs);
  }); });

  // simulate drive (experiment 6, Sec. 4.3)
  auto dcfg = std::make_shared<sim::DriveRunConfig>();
  auto dstepper = std::make_shared<std::string>(sim::to_string(dcfg->integrator.stepper));
  auto* drive = sim_cmd->add_subcommand(
      "drive", "Chain at rest driven at u_0(t) = A0 sin(omega0 t) chi(t), clamped far end (Sec. 4.3)");
  add_model_options(*drive, dcfg->params, false);
  const auto& drive_schema = jobs::drive_options();
  const auto drive_help = [&drive_schema](const char* key) { return schema_help(drive_schema, key); };
  add_integer(*drive, "--sites", dcfg->beads, 10, std::numeric_limits<std::int64_t>::max(), drive_help("sites"));
  add_number(*drive, "--amplitude", dcfg->amplitude, drive_help("amplitude"));
  add_number(*drive, "--omega0", dcfg->omega0, drive_help("omega0"));
  add_number(*drive, "--ramp-rate", dcfg->ramp_rate, drive_help("ramp_rate"));
  add_number(*drive, "--switch-off-time", dcfg->t_m, drive_help("switch_off_time"));
  add_number(*drive, "--t-end", dcfg->t_end, drive_help("t_end"));
  add_number(*drive, "--sample-every", dcfg->sample_every, drive_help("sample_every"));
  add_number(*drive, "--spacetime-every", dcfg->spacetime_every, drive_help("spacetime_every"));
  add_number_list(*drive, "--snapshots", dcfg->snapshot_times, drive_help("snapshot_times"));
  add_number(*drive, "--front-fraction", dcfg->front_fraction, drive_help("front_fraction"));
  add_number(*drive, "--front-fit-start", dcfg->front_fit_start, drive_help("front_fit_start"));
  add_number(*drive, "--front-fit-end", dcfg->front_fit_end, drive_help("front_fit_end"));
  add_number(*drive, "--checkpoint-every", dcfg->checkpoint_every, drive_help("checkpoint_every"));
  add_integrator_options(*drive, dcfg->integrator, *dstepper, drive_schema);
  add_output_options(*drive, outputs, true, subcommand_out);
  add_examples(*drive, {"lrchain simulate drive --rho 10 --sites 2000 --omega0 2.1 --t-end 2400 --out out/exp6"});
  drive->callback([=] { with_option_names(jobs::drive_options(), [&] {
    refuse_ignored_options(*drive, *out, {}, "");
    run_lattice_command(*dcfg, *dstepper, outputs);
  }); });

  // simulate modulated (experiment 7, Sec. 5.1)
  auto mcfg = std::make_shared<sim::ModulatedRunConfig>();
  auto mstepper = std::make_shared<std::string>(sim::to_string(mcfg->integrator.stepper));
  auto* mod = sim_cmd->add_subcommand(
      "modulated", "Periodic chain from the modulated acoustic wave eq:cimi, checkpoint/restart (Sec. 5.1)");
  add_model_options(*mod, mcfg->params, false);
  const auto& mod_schema = jobs::modulated_options();
  const auto mod_help = [&mod_schema](const char* key) { return schema_help(mod_schema, key); };
  add_integer(*mod, "--sites", mcfg->N, 8, std::numeric_limits<std::int64_t>::max(), mod_help("sites"));
  add_parameter(*mod, "--epsilon", mcfg->epsilon, modulation_amplitude_range,
                "default " + jobs::default_text(jobs::find_option(mod_schema, "epsilon")));
  add_number(*mod, "--theta-waves", mcfg->theta_waves, mod_help("theta_waves"));
  add_number(*mod, "--modulation-depth", mcfg->b, mod_help("modulation_depth"));
  add_number(*mod, "--t-end", mcfg->t_end, mod_help("t_end"));
  add_number(*mod, "--sample-every", mcfg->sample_every, mod_help("sample_every"));
  add_number_list(*mod, "--snapshots", mcfg->snapshot_times, mod_help("snapshot_times"));
  add_number(*mod, "--contrast-threshold", mcfg->contrast_threshold, mod_help("contrast_threshold"));
  add_number(*mod, "--speed-fit-start", mcfg->speed_fit_start, mod_help("speed_fit_start"));
  add_number(*mod, "--speed-fit-end", mcfg->speed_fit_end, mod_help("speed_fit_end"));
  add_number(*mod, "--checkpoint-every", mcfg->checkpoint_every, mod_help("checkpoint_every"));
  add_integrator_options(*mod, mcfg->integrator, *mstepper, mod_schema);
  add_output_options(*mod, outputs, true, subcommand_out);
  add_examples(*mod, {"lrchain simulate modulated --sites 401 --theta-waves 252 --t-end 45000 --out out/exp7"});
  mod->callback([=] { with_option_names(jobs::modulated_options(), [&] {
    refuse_ignored_options(*mod, *out, {}, "");
    run_lattice_command(*mcfg, *mstepper, outputs);
  }); });

  sim_cmd->callback([=] { with_option_names({}, [&] {
    if (!sim_cmd->get_subcommands().empty()) return;
    if (config->empty())
      throw InvalidParameter("config", "give a subcommand (bright, drive, modulated, ring) or --config FILE.toml");
    if (run_model_config(*config, *sim_cmd, model_run_output(outputs)))
      return;  // a model file's bright or ring config (simulate_model_bright.cpp)
    const std::string kind = jobs::experiment_kind(*config);
    if (kind == "drive") {
      auto dc = jobs::load_drive_config(*config);
      dc.run.restart_file = *restart;
      dc.run.checkpoint_file = *checkpoint;
      dc.run.max_memory = *max_memory;
      refuse_without_out(*sim_cmd, !out->empty() ? *out : dc.out_dir, output_file_options);
      run_and_report(dc.run, !out->empty() ? *out : dc.out_dir, *style);
      return;
    }
    if (kind == "modulated") {
      auto mc = jobs::load_modulated_config(*config);
      mc.run.restart_file = *restart;
      mc.run.checkpoint_file = *checkpoint;
      mc.run.max_memory = *max_memory;
      refuse_without_out(*sim_cmd, !out->empty() ? *out : mc.out_dir, output_file_options);
      run_and_report(mc.run, !out->empty() ? *out : mc.out_dir, *style);
      return;
    }
    jobs::ExperimentConfig ec = jobs::load_experiment_config(*config);
    const std::string dir = !out->empty() ? *out : ec.out_dir;
    ec.bright.restart_file = *restart;
    ec.bright.checkpoint_file = *checkpoint;
    ec.bright.max_memory = *max_memory;
    refuse_without_out(*sim_cmd, dir, output_file_options);
    if (ec.experiment == "bright") run_and_report(ec.bright, dir, *style);
  }); });
}

}  // namespace lrchain::cli
