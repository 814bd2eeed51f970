// `lrchain wave solve|continue|stability`: exact periodic travelling waves of any model and their
// Floquet-Bloch growth rates (docs/waves.md), the job of lrchain/jobs/wave_job.hpp on the command line:
// options -> WaveConfig, the result -> JSON on stdout and the exit code (3: no wave); files in --out.
#include <CLI/CLI.hpp>
#include <cstdio>
#include <memory>
#include <optional>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "commands.hpp"
#include "figure_format_option.hpp"
#include "help_text.hpp"
#include "lrchain/errors.hpp"
#include "lrchain/jobs/wave_job.hpp"
#include "lattice_job.hpp"
#include "model_option.hpp"
#include "options.hpp"
#include "stop_signals.hpp"

namespace lrchain::cli {

namespace {
using namespace lrchain::jobs::wave;

struct WaveArgs {
  WaveConfig config;
  Params chain;          // the resonant chain's --alpha/--delta0/--kappa/--rho (aliases of --set)
  ModelSelection model;  // --model FILE --set NAME=VALUE (empty: the resonant chain)
  bool json_out = false;
};

std::string wave_help(const std::string& key) { return jobs::help_text(jobs::find_option(wave_options(), key)); }

// The options every step takes.
void add_common(CLI::App& sub, WaveArgs& a) {
  WaveConfig& c = a.config;
  add_model_options(sub, a.chain, false);
  add_model_file_options(sub, a.model);
  sub.add_option("--branch", c.branch, wave_help("branch"))->type_name("NAME");
  add_number(sub, "--theta", c.theta, wave_help("theta"))->required();
  add_integer(sub, "--harmonics", c.initial_harmonics, 0, 1000000, wave_help("initial_harmonics"));
  add_integer(sub, "--max-harmonics", c.max_harmonics, 0, 1000000, wave_help("max_harmonics"));
  add_number(sub, "--tail-tolerance", c.tail_tolerance, wave_help("tail_tolerance"));
  add_number(sub, "--tolerance", c.tolerance, wave_help("tolerance"));
  add_integer(sub, "--max-iterations", c.max_iterations, 0, 1000000, wave_help("max_iterations"));
  sub.add_flag("--json", a.json_out, "print the JSON summary on one line (default: indented)");
  sub.add_option("--out", c.out, "output directory: profile.csv, branch.csv, growth.csv and growth.gp, summary.json, with --format hdf5 result.h5 (default: none, no files)")
      ->type_name("DIR");
  add_figure_format(sub);
  sub.add_option("--format", c.format, wave_help("format"))
      ->check(CLI::IsMember({"csv", "hdf5"}).description(""))
      ->type_name("csv|hdf5");
}

// The amplitude of solve and stability.
void add_amplitude(CLI::App& sub, WaveArgs& a) {
  add_number(sub, "--amplitude", a.config.amplitude, wave_help("amplitude"))->required();
  add_integer(sub, "--ramp", a.config.ramp, 0, 1000000, wave_help("ramp"));
}

// Validates, runs and reports one job: JSON on stdout, then exit 3 when there is no wave.
void run_job(const WaveArgs& a, WaveStep step, const CLI::App& cmd) {
  refuse_without_out(cmd, a.config.out, {"--format", "--figure-format"});
  WaveConfig config = a.config;
  config.step = step;
  const Model model = load_selected_model(a.model, cmd, a.chain, true);
  const LatticeCode code = validated_lattice_job(config, model, a.model, wave_options());
  std::optional<StopSignals> signals;  // a ring run (fate) stops at its next carrier period, with its files so far
  if (step == WaveStep::fate) {
    signals.emplace();
    config.stop = StopSignals::flag();
  }
  const WaveResult r = run(config);
  const nlohmann::json j = config.out.empty() ? to_json(r) : write(r, config.out);
  std::printf("%s\n", j.dump(a.json_out ? -1 : 2).c_str());
  std::fflush(stdout);
  if (r.fate && r.fate->interrupted)
    throw Interrupted(StopSignals::received(), fmt::format("interrupted at t = {:.6g}", r.fate->t.back()));
  if (r.failure) throw NumericalFailure(*r.failure);
}

}  // namespace

void register_wave(CLI::App& app) {
  auto* wave = app.add_subcommand(
      "wave", "Exact periodic travelling waves u_n(t) = U(theta n - omega t) of any lattice (docs/waves.md): "
              "collocation in the phase and Newton, continuation in the amplitude, Floquet-Bloch growth rates, "
              "each beside the NLS prediction");
  wave->require_subcommand(1);
  add_examples(*wave, {"lrchain wave solve --model klein_gordon --branch branch0 --theta 3*pi/4 --amplitude 0.1",
                       "lrchain wave stability --model fput --branch acoustic --theta 2.5 --amplitude 0.02 --out out/wave"});
  auto args = std::make_shared<WaveArgs>();
  auto* solve_cmd = wave->add_subcommand("solve", "The wave at one amplitude: profile, omega, harmonics used, residual");
  add_common(*solve_cmd, *args);
  add_amplitude(*solve_cmd, *args);
  add_examples(*solve_cmd, {"lrchain wave solve --model klein_gordon --branch branch0 --theta 3*pi/4 --amplitude 0.1"});
  solve_cmd->callback([args, solve_cmd] { run_job(*args, WaveStep::solve, *solve_cmd); });
  auto* cont = wave->add_subcommand("continue", "The branch omega(A) through increasing amplitudes, with h A^2/4 beside it");
  add_common(*cont, *args);
  add_number_list(*cont, "--amplitudes", args->config.amplitudes, wave_help("amplitudes"));  // validate requires it
  add_examples(*cont, {"lrchain wave continue --model fput --branch acoustic --theta 2.5 --amplitudes 0.05 0.1 0.2 0.4"});
  cont->callback([args, cont] { run_job(*args, WaveStep::branch, *cont); });
  auto* stab = wave->add_subcommand(
      "stability", "Solve, then the growth rate max Re lambda of the Floquet-Bloch spectrum over K in (0, pi]: the "
                   "unstable bands, the largest rate and its K, and the NLS modulational-instability curve");
  add_common(*stab, *args);
  add_amplitude(*stab, *args);
  add_integer(*stab, "--k-points", args->config.k_points, 0, 1000000, wave_help("k_points"));
  add_number(*stab, "--unstable-tolerance", args->config.unstable_tolerance, wave_help("unstable_tolerance"));
  add_examples(*stab, {"lrchain wave stability --model fput --branch acoustic --theta 2.5 --amplitude 0.02 --out out/wave"});
  stab->callback([args, stab] { run_job(*args, WaveStep::stability, *stab); });
  auto* fate = wave->add_subcommand(
      "fate", "What the wave becomes: stability at the nearest ring wavenumber, then the wave plus noise on a ring of "
              "--ring-sites sites for --periods carrier periods, classified stable, modulated, localized or "
              "disordered by its deviation, energy participation and spectral entropy (docs/waves.md)");
  add_common(*fate, *args);
  add_amplitude(*fate, *args);
  add_integer(*fate, "--k-points", args->config.k_points, 0, 1000000, wave_help("k_points"));
  add_number(*fate, "--unstable-tolerance", args->config.unstable_tolerance, wave_help("unstable_tolerance"));
  add_integer(*fate, "--ring-sites", args->config.ring_sites, 0, 1000000, wave_help("ring_sites"));
  add_number(*fate, "--noise", args->config.noise, wave_help("noise"));
  add_number(*fate, "--modulation", args->config.modulation, wave_help("modulation"));
  add_integer(*fate, "--seed", args->config.seed, 0, 2147483647, wave_help("seed"));
  add_number(*fate, "--periods", args->config.periods, wave_help("periods"));
  add_integer(*fate, "--steps-per-period", args->config.steps_per_period, 0, 1000000, wave_help("steps_per_period"));
  add_examples(*fate, {"lrchain wave fate --model fput --theta 2.5 --amplitude 0.2 --periods 500 --out out/fate"});
  fate->callback([args, fate] { run_job(*args, WaveStep::fate, *fate); });
  auto* standing = wave->add_subcommand(
      "standing", "The standing wave (the sum of the two counter-propagating waves) of a reflection-symmetric model: "
                  "a time-periodic orbit on one spatial period of the ring, continued in A, and its Floquet "
                  "multipliers on a ring of --ring-sites sites (docs/waves.md)");
  add_common(*standing, *args);
  add_amplitude(*standing, *args);
  add_integer(*standing, "--ring-sites", args->config.ring_sites, 0, 1000000, wave_help("ring_sites"));
  add_examples(*standing, {"lrchain wave standing --model fput --theta 2*pi/5 --amplitude 0.1 --ring-sites 20"});
  standing->callback([args, standing] { run_job(*args, WaveStep::standing, *standing); });
}

}  // namespace lrchain::cli
