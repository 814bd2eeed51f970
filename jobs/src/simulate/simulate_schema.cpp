// The simulate jobs' option schemas (simulate_schema.hpp): defaults read from default-constructed
// run configs, help texts as `lrchain simulate <job> --help` shows them.
#include "lrchain/jobs/simulate/simulate_schema.hpp"

#include <fmt/format.h>

#include <numbers>

#include "lrchain/config/option_caps.hpp"
#include "lrchain/params.hpp"
#include "lrchain/sim/resonant_chain_bright_run.hpp"
#include "lrchain/sim/drive_run.hpp"
#include "lrchain/sim/bright_run.hpp"
#include "lrchain/sim/modulated_run.hpp"
#include "lrchain/sim/ring_run.hpp"
#include "lrchain/sim/strain_sites.hpp"

namespace lrchain::jobs {

namespace {

using nlohmann::json;

// An option that CLI and Python spell alike (--sample-every, sample_every), help "{doc} (default {default})".
JobOption both(std::string key, json default_value, std::string range, std::string doc,
               std::string help = "{doc} (default {default})") {
  std::string cli = "--" + key;
  for (char& ch : cli)
    if (ch == '_') ch = '-';
  return {key, cli, key, {}, std::move(default_value), false, std::move(range), std::move(doc), std::move(help)};
}

// The same option under another CLI spelling (--snapshots for snapshot_periods).
JobOption renamed(std::string cli, JobOption o) {
  o.cli = std::move(cli);
  return o;
}
JobOption cli_only(JobOption o) {
  o.python.clear();
  return o;
}
JobOption python_only(JobOption o) {
  o.cli.clear();
  return o;
}
JobOption with_note(std::string note, JobOption o) {
  o.default_note = std::move(note);
  return o;
}

const char* const steppers =
    "rkf78, dopri5, symplectic (McLachlan 4), srkn11b, srkn14a (Blanes-Moan 6) or ss17 (McLachlan 8)";

// stepper, abs_tol, rel_tol, dt of a run's IntegratorOptions (its defaults; the drive's tolerances
// are 1e-10, the others' 1e-12); `automatic_dt`: the fixed-step steppers choose their step.
void add_integrator(std::vector<JobOption>& options, const sim::IntegratorOptions& d) {
  options.push_back(both("stepper", std::string(sim::to_string(d.stepper)), steppers, "the integrator", "{range}; default {default}"));
  options.push_back(both("abs_tol", d.abs_tol, "> 0", "absolute local error tolerance"));
  options.push_back(both("rel_tol", d.rel_tol, "> 0", "relative local error tolerance"));
  options.push_back(d.automatic_dt
                        ? both("dt", d.dt, "> 0",
                               "largest step of the fixed-step steppers (default: chosen by a probe run), or the "
                               "initial step of the adaptive ones",
                               "largest step of the fixed-step steppers (default: chosen by a 2 T_b probe run so "
                               "that the relative energy error stays below 2e-10), or the initial step of the "
                               "adaptive ones (default {default})")
                        : both("dt", d.dt, "> 0", "initial step (adaptive) or fixed/maximal step (symplectic, srkn*)",
                               "{doc}, default {default}"));
}

// checkpoint_every (the command line's; `checkpoint_help` says what 0 means), max_memory (Python's: the
// command takes --max-memory SIZE) and the integrator's options of a lattice run's config `d`.
template <class Config>
void add_run_options(std::vector<JobOption>& options, const Config& d, const char* checkpoint_doc,
                     const char* checkpoint_help) {
  options.push_back(cli_only(both("checkpoint_every", d.checkpoint_every, ">= 0", checkpoint_doc, checkpoint_help)));
  options.push_back(
      python_only(both("max_memory", d.max_memory, ">= 0", "bytes the run may use (0: the machine's available memory)")));
  add_integrator(options, d.integrator);
}

std::vector<JobOption> make_bright() {
  const sim::BrightRunConfig d;
  const auto sites = sim::strain_site_count(d.N);
  std::vector<JobOption> o{
      {"branch", "--branch", "branch", {}, std::string(to_string(d.branch)), false,
       "optical or acoustic, required (with --model: a branch of the model, by default its only one)",
       "dispersion branch of the carrier", "{range}"},
      {"theta", "--theta", "theta", {}, std::numbers::pi / 2, true, "in (0, pi]", "carrier wavenumber",
       "{doc} {range}, e.g. pi/2", "pi/2"},
      with_note("sign(h_tilde)*1e-4", both("detuning", nullptr, "", "omega_b - omega")),
      both("n0", d.n0, "|n0| <= N = (sites - 1)/2", "initial breather centre n0", "{doc}, {range} (default {default})"),
      both("sites", sites,
           fmt::format("odd, in [{}, {}] (with --model [{}, {}])", sim::bright_sites.least, sim::bright_sites.most,
                       sim::model_bright_sites.least, sim::model_bright_sites.most),
           "odd number of lattice sites 2N + 1, n = -N..N (strains of the resonant chain and of translation-invariant "
           "models, displacements of on-site models)",
           fmt::format("{{doc}} (default {{default}}, N = {}; with --model {} or more)", d.N,
                       sim::model_bright_sites.least)),
      both("periods", d.periods, "> 0", "run length in breather periods T_b"),
      both("sample_every", d.sample_every, "> 0", "sampling interval in T_b"),
      both("spacetime_every", d.spacetime_every, "> 0", "energy-density row interval in T_b"),
      with_note("none, the whole run only",
                renamed("--error-window", both("error_window_end", nullptr, "", "also report max E_x, E_y for t <= this time",
                                               "{doc} (default: {default})"))),
      renamed("--snapshots", both("snapshot_periods", d.snapshot_periods, ">= 0 each", "snapshot times in T_b")),
      python_only(both("centre_window", d.centre_window, ">= 1", "sites m of the energy centre (eq. (41))")),
      both("ansatz_ends", d.ansatz_ends, "true|false", "end beads follow the ansatz (emitting boundary conditions, Sec. 4.2)",
           "{doc}"),
  };
  add_run_options(o, d, "periods T_b between checkpoints", "{doc} (default {default}: only on SIGINT/SIGTERM)");
  return o;
}

// `simulate bright --model`: the options of `simulate bright` that a model run takes (ModelBrightConfig's
// defaults are BrightRunConfig's: the test of this schema checks them).
std::vector<JobOption> make_model_bright() {
  const sim::ModelBrightConfig d;
  std::vector<JobOption> o;
  for (const char* key : {"branch", "theta", "detuning", "n0", "sites", "periods", "sample_every", "ansatz_ends", "dt"})
    o.push_back(find_option(bright_options(), key));
  for (JobOption& option : o) {
    if (option.key == "branch") {
      option.range = "a branch of the model (default: its only one; required when it has several)";
      option.required = false;
    }
    if (option.key == "sites") {
      option.default_value = sim::strain_site_count(d.N);
      option.range = fmt::format("odd, in [{}, {}]", sim::model_bright_sites.least, sim::model_bright_sites.most);
    }
    if (option.key == "periods") option.default_value = d.periods;
    if (option.key == "sample_every") option.default_value = d.sample_every;
    if (option.key == "n0") option.default_value = d.n0;
    if (option.key == "dt") {
      option.default_value = nullptr;
      option.default_note = "from the fastest linear mode";
      option.doc = "the srkn11b step";
    }
  }
  return o;
}

std::vector<JobOption> make_drive() {
  const sim::DriveRunConfig d;
  std::vector<JobOption> o{
      both("sites", d.beads, ">= 10", "lattice sites: beads n = 1..sites, each with its resonator, driven at n = 0, far end clamped"),
      both("amplitude", d.amplitude, "in (0, delta0]", "driving amplitude A0", "A0, {range} (default {default})"),
      both("omega0", d.omega0, "in the optical band", "driving frequency", "{doc}, {range} (default {default})"),
      both("ramp_rate", d.ramp_rate, "> 0", "r of chi(t)"),
      both("switch_off_time", d.t_m, ">= 0", "switch-off time t_m of chi(t)"),
      both("t_end", d.t_end, "> 0", "final time"),
      both("sample_every", d.sample_every, "> 0", "series interval"),
      both("spacetime_every", d.spacetime_every, "> 0", "e_n row interval"),
      renamed("--snapshots", both("snapshot_times", d.snapshot_times, ">= 0 each", "snapshot times")),
      both("front_fraction", d.front_fraction, "in (0, 1)", "front = last n with e_n > this * max e_n"),
      both("front_fit_start", d.front_fit_start, ">= 0", "front-speed fit from"),
      both("front_fit_end", d.front_fit_end, "> 0", "front-speed fit to"),
  };
  add_run_options(o, d, "time between checkpoints", "{doc} (default {default}: only on SIGINT/SIGTERM)");
  return o;
}

std::vector<JobOption> make_modulated() {
  const sim::ModulatedRunConfig d;
  const PhysicalRange& eps = modulation_amplitude_range;
  std::vector<JobOption> o{
      both("sites", d.N, ">= 8", "lattice sites N of the periodic chain, n = 0..N-1"),
      both("epsilon", d.epsilon, "in " + eps.interval(), eps.meaning, "{doc}, {range} (default {default})"),
      both("theta_waves", d.theta_waves, "", "carrier theta0 = this * pi / N, N = --sites"),
      both("modulation_depth", d.b, "", "modulation depth b of eq. (43)"),
      both("t_end", d.t_end, "> 0", "final time"),
      both("sample_every", d.sample_every, "> 0", "series and e_n row interval"),
      renamed("--snapshots", both("snapshot_times", d.snapshot_times, ">= 0 each", "snapshot times")),
      both("contrast_threshold", d.contrast_threshold, "> 0",
           "instability when (max-min)/mean of smoothed e_n exceeds this"),
      python_only(both("dark_window", d.dark_window, ">= 1", "running mean (sites) before locating min e_n")),
      both("speed_fit_start", d.speed_fit_start, ">= 0", "dark-speed fit from"),
      both("speed_fit_end", d.speed_fit_end, "> 0", "dark-speed fit to"),
  };
  add_run_options(o, d, "time between checkpoints", "{doc} (default {default}, 0: none)");
  return o;
}

std::vector<JobOption> make_ring() {
  const sim::RingRunConfig d;
  return {
      {"branch", "--branch", "branch", {}, nullptr, false, "a branch of the model",
       "branch name of the model (acoustic, optical, branch0, ...); default: its only one, required when it has several",
       "{doc}"},
      {"theta", "--theta", "theta", {}, nullptr, true, "in (0, pi]", "carrier wavenumber 2 pi k / N", "{doc} {range}, e.g. pi/2"},
      both("amplitudes", d.amplitudes, "each in (0, 10]", "plane-wave amplitudes U of the first field"),
      with_note("the smallest N >= 8 with theta N / (2 pi) whole",
                both("sites", nullptr, fmt::format("[{}, {}]", config::ring_sites.least, config::ring_sites.most),
                     "ring size N", "{doc} (default: {default})")),
      both("periods", d.periods, "> 0", "carrier periods per frequency measurement"),
      both("steps_per_period", d.steps_per_period, "> 0", "srkn11b steps per carrier period"),
      with_note("a tenth of the smallest --amplitudes",
                both("packet_amplitude", nullptr, "in (0, 10]", "wave-packet amplitude", "{doc} {range} (default: {default})")),
      both("packet_width", d.packet_width, "> 0", "Gaussian width of the packet in sites"),
  };
}

}  // namespace

const std::vector<JobOption>& bright_options() { return schema_once<make_bright>(); }
const std::vector<JobOption>& model_bright_options() { return schema_once<make_model_bright>(); }
const std::vector<JobOption>& drive_options() { return schema_once<make_drive>(); }
const std::vector<JobOption>& modulated_options() { return schema_once<make_modulated>(); }
const std::vector<JobOption>& ring_options() { return schema_once<make_ring>(); }

}  // namespace lrchain::jobs
