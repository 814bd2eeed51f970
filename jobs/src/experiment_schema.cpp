// The schemas of the simulate configs ("bright", "drive", "modulated"): every key, its type,
// range and default (experiment_config.hpp; docs/configs.md is generated from them).
#include <map>

#include "lrchain/jobs/experiment_config.hpp"
#include "lrchain/jobs/more_experiment_config.hpp"
#include "lrchain/sim/strain_sites.hpp"
#include "toml_reading.hpp"

namespace lrchain::jobs {

using namespace lrchain::sim;  // the numerics this job layer runs

namespace {

using namespace lrchain::config;

constexpr std::int64_t max_sites = 50'000'000;  // lattice sizes of the drive and modulated chains, n0, windows

std::string numbers_text(const std::vector<double>& values) {
  std::string s = "[";
  for (std::size_t i = 0; i < values.size(); ++i) s += (i ? ", " : "") + number_text(values[i]);
  return s + "]";
}

// [bright] of Sec. 4.1-4.3 (BrightRunConfig).
std::shared_ptr<const TableSchema> bright_table() {
  const BrightRunConfig d;
  const auto positive = NumberRange::positive(), non_negative = NumberRange::non_negative();
  return std::make_shared<const TableSchema>(TableSchema{
      "a bright breather started from the NLS ansatz (Sec. 4.1-4.3)",
      {choice("branch", branch_spellings(), std::string(to_string(d.branch)),
              "dispersion branch of the carrier (opt and + mean optical, acs and - acoustic)"),
       number("theta", NumberRange::any(), "", "carrier wavenumber theta").require(),
       number("detuning", NumberRange::any(), "sign(h_tilde) 1e-4", "omega_b - omega"),
       number("n0", NumberRange::between(-double(max_sites), double(max_sites), false, false), number_text(d.n0),
              "initial centre (site), in [-N, N] with sites = 2N + 1"),
       integer("sites", bright_sites.least, bright_sites.most, std::to_string(strain_site_count(d.N)),
               "odd number of strain sites 2N + 1, n = -N..N"),
       number("periods", positive, number_text(d.periods), "run length in breather periods T_b"),
       number("sample_every", positive, number_text(d.sample_every), "E_x, E_y, energy, centre sampled every this many T_b"),
       number("spacetime_every", positive, number_text(d.spacetime_every), "an energy density row every this many T_b"),
       numbers("snapshot_periods", non_negative, numbers_text(d.snapshot_periods), "snapshot times in T_b"),
       integer("centre_window", 1, max_sites, std::to_string(d.centre_window), "sites m of the energy centre (eq. (41))"),
       number("error_window_end", NumberRange::any(), "none",
              "also report max E_x, E_y over times t <= this (when > 0)"),
       boolean("ansatz_ends", d.ansatz_ends ? "true" : "false", "end beads follow the ansatz (emitting ends)"),
       number("trailing_fit_start", non_negative, "0 (off)",
              "track a structure behind the breather from this time on (> 0 to enable)"),
       number("trailing_gap", non_negative, number_text(d.trailing.gap),
              "sites between the breather's centre and the searched region"),
       number("checkpoint_every", non_negative, number_text(d.checkpoint_every),
              "T_b between checkpoints (0: only on SIGINT/SIGTERM; > 0 also writes one at the end)")},
      std::nullopt,
      {{"N", "sites", half_width_renamed_note}}});
}

// [drive] of Sec. 4.3 (DriveRunConfig).
std::shared_ptr<const TableSchema> drive_table() {
  const DriveRunConfig d;
  const auto positive = NumberRange::positive(), non_negative = NumberRange::non_negative();
  return std::make_shared<const TableSchema>(TableSchema{
      "a chain at rest driven at its first bead (Sec. 4.3)",
      {integer("sites", 10, max_sites, std::to_string(d.beads), "beads n = 1..sites, far end clamped"),
       number("amplitude", config::range_of(delta0_range), number_text(d.amplitude),
              "driving amplitude A0, at most the precompression overlap delta0"),
       number("omega0", positive, number_text(d.omega0), "driving frequency"),
       number("ramp_rate", positive, number_text(d.ramp_rate), "r of the envelope chi(t)"),
       number("switch_off_time", non_negative, number_text(d.t_m), "switch-off time t_m of chi(t)"),
       number("t_end", positive, number_text(d.t_end), "run length"),
       number("sample_every", positive, number_text(d.sample_every), "series sampled every this time"),
       number("spacetime_every", positive, number_text(d.spacetime_every), "an energy density row every this time"),
       numbers("snapshot_times", non_negative, numbers_text(d.snapshot_times), "velocity snapshot times"),
       number("front_fraction", NumberRange::between(0, 1, true, true), number_text(d.front_fraction),
              "front = last site with e_n above this fraction of max e_n"),
       number("front_fit_start", non_negative, number_text(d.front_fit_start), "start of the front-speed fit"),
       number("front_fit_end", positive, number_text(d.front_fit_end), "end of the front-speed fit"),
       number("checkpoint_every", non_negative, number_text(d.checkpoint_every),
              "time between checkpoints (0: only on SIGINT/SIGTERM; > 0 also writes one at the end)")},
      std::nullopt,
      {{"beads", "sites"}, {"t_m", "switch_off_time"}}});
}

// [modulated] of Sec. 5.1 (ModulatedRunConfig).
std::shared_ptr<const TableSchema> modulated_table() {
  const ModulatedRunConfig d;
  const auto positive = NumberRange::positive(), non_negative = NumberRange::non_negative();
  return std::make_shared<const TableSchema>(TableSchema{
      "a periodic chain started from a modulated acoustic wave (Sec. 5.1)",
      {integer("sites", 8, max_sites, std::to_string(d.N), "sites N of the periodic chain, n = 0..N-1"),
       number("epsilon", config::range_of(modulation_amplitude_range), number_text(d.epsilon),
              modulation_amplitude_range.meaning),
       number("theta_waves", positive, number_text(d.theta_waves), "carrier theta0 = theta_waves pi / N"),
       number("modulation_depth", NumberRange::between(0, 1, false, true), number_text(d.b),
              "modulation depth b of eq. (43)"),
       number("t_end", positive, number_text(d.t_end), "run length"),
       number("sample_every", positive, number_text(d.sample_every), "series and energy density rows every this time"),
       numbers("snapshot_times", non_negative, numbers_text(d.snapshot_times), "velocity snapshot times"),
       number("contrast_threshold", positive, number_text(d.contrast_threshold),
              "instability: first time (max e - min e)/mean e exceeds this"),
       integer("dark_window", 1, max_sites, std::to_string(d.dark_window), "running mean (sites) before locating min e_n"),
       number("speed_fit_start", non_negative, number_text(d.speed_fit_start), "start of the dark-breather speed fit"),
       number("speed_fit_end", non_negative, number_text(d.speed_fit_end), "end of the dark-breather speed fit"),
       number("checkpoint_every", non_negative, number_text(d.checkpoint_every),
              "time between checkpoints (0: none)")},
      std::nullopt,
      {{"N", "sites"}, {"b", "modulation_depth"}}});
}

}  // namespace

std::vector<std::string> experiment_kinds() { return {"bright", "drive", "modulated"}; }

const config::TableSchema& experiment_schema(std::string_view kind) {
  static const std::map<std::string, TableSchema, std::less<>> schemas = [] {
    const BrightRunConfig b;
    const DriveRunConfig d;
    const ModulatedRunConfig m;
    const auto steppers = config::all_steppers();
    std::map<std::string, TableSchema, std::less<>> s;
    s.emplace("bright", config::top_level_schema("bright", b.params, b.integrator, steppers, bright_table()));
    // The driven chain is not autonomous: adaptive steppers only.
    s.emplace("drive", config::top_level_schema("drive", d.params, d.integrator, {"rkf78", "dopri5"}, drive_table()));
    s.emplace("modulated", config::top_level_schema("modulated", m.params, m.integrator, steppers, modulated_table()));
    return s;
  }();
  const auto it = schemas.find(kind);
  if (it == schemas.end())
    throw InvalidParameter("experiment", "must be one of \"bright\", \"drive\", \"modulated\"");
  return it->second;
}

std::string experiment_configs_markdown() {
  std::string md;
  for (const auto& kind : experiment_kinds()) {
    const TableSchema& top = experiment_schema(kind);
    md += "### `experiment = \"" + kind + "\"`\n\nTop level:\n\n" + markdown_table(top);
    for (const auto& k : top.keys) {
      if (k.type != ValueType::table) continue;
      md += "\n`[" + k.name + "]`" + (k.required ? " (required)" : "") + ": " + k.table->meaning + ".\n\n" +
            markdown_table(*k.table);
      if (k.table->renamed.empty()) continue;
      md += "\nRenamed keys of `[" + k.name + "]` (an old key is an error naming the new one):\n\n";
      for (const auto& r : k.table->renamed)
        md += "- `" + r.old_name + "`: use `" + r.new_name + "`" + (r.note.empty() ? "" : ", " + r.note) + "\n";
    }
    md += "\n";
  }
  return md;
}

std::string experiment_kind(const config::Document& doc) {
  static const TableSchema first_look{"", {choice("experiment", experiment_kinds(), "", "").require()}, anything("")};
  std::string kind;
  check(doc, first_look).read("experiment", kind);
  return kind;
}

std::string experiment_kind(const std::filesystem::path& file) {
  return experiment_kind(config::Document::from_file(file));
}

}  // namespace lrchain::jobs
