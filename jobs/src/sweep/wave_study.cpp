// The "wave stability" sweep job (wave_study.hpp): the wave job's Config read from [wave], run, and
// its result reduced to scalars and rows.
#include "wave_study.hpp"

#include <atomic>
#include <cmath>
#include <limits>
#include <numbers>
#include <optional>

#include <fmt/format.h>

#include "lrchain/errors.hpp"
#include "lrchain/jobs/wave_job.hpp"
#include "model_jobs.hpp"
#include "study_options.hpp"

namespace lrchain::jobs::sweep {

using namespace lrchain::config;
using jobs::wave::WaveConfig;

namespace {

constexpr double no_value = std::numeric_limits<double>::quiet_NaN();

// The wave job's step of a sweep kind: "stability", "fate" or "standing".
std::string step_of(std::string_view kind) {
  return kind == "wave fate" ? "fate" : kind == "wave standing" ? "standing" : "stability";
}

// [wave] into the job's config (its kind's step) at the point's model, with the job's checks.
WaveConfig read_wave(std::string_view kind, const Document& doc, const CheckedTable& root, const PointModel& p) {
  WaveConfig c;
  c.step = kind == "wave fate"       ? jobs::wave::WaveStep::fate
           : kind == "wave standing" ? jobs::wave::WaveStep::standing
                                     : jobs::wave::WaveStep::stability;
  c.model = &*p.model;
  c.kernels = p.kernels;
  const CheckedTable w = *root.table("wave");
  w.read("branch", c.branch);
  w.read("theta", c.theta);
  w.read("amplitude", c.amplitude);
  std::int64_t integer = 0;
  if (w.read("ramp", integer)) c.ramp = Index(integer);
  if (w.read("harmonics", integer)) c.initial_harmonics = Index(integer);
  if (w.read("max_harmonics", integer)) c.max_harmonics = Index(integer);
  if (w.read("max_iterations", integer)) c.max_iterations = Index(integer);
  if (c.step != jobs::wave::WaveStep::standing && w.read("k_points", integer)) c.k_points = Index(integer);
  if (c.step != jobs::wave::WaveStep::stability && w.read("ring_sites", integer)) c.ring_sites = Index(integer);
  if (c.step == jobs::wave::WaveStep::fate) {
    if (w.read("seed", integer)) c.seed = Index(integer);
    if (w.read("steps_per_period", integer)) c.steps_per_period = Index(integer);
    w.read("noise", c.noise);
    w.read("modulation", c.modulation);
    w.read("periods", c.periods);
  }
  w.read("tail_tolerance", c.tail_tolerance);
  w.read("tolerance", c.tolerance);
  if (c.step != jobs::wave::WaveStep::standing) w.read("unstable_tolerance", c.unstable_tolerance);
  try {
    jobs::wave::validate(c);
  } catch (const InvalidParameter& e) {  // the Config key, spelled as [wave] names it
    throw table_key_error(doc, "wave", e, jobs::wave::wave_options());
  }
  return c;
}

// A "wave standing" point: the standing wave's scalars (wave_scalar_names) and one row per Floquet multiplier.
JobResult standing_point(const WaveConfig& c) {
  const jobs::wave::WaveResult w = jobs::wave::run(c);
  JobResult r;
  if (w.failure || !w.standing_floquet) {
    r.status = PointStatus::numerical_failure;
    r.reason = w.failure.value_or("no Floquet multipliers");  // names the amplitude and theta
    return r;
  }
  const auto& wave = w.standing.back();
  const auto& f = *w.standing_floquet;
  // growth per unit time of the fastest perturbation, ln|mu| / T: 0 when every |mu| is within the
  // Floquet tolerance of the unit circle (stable)
  const double growth_rate = f.stable ? 0.0 : std::log(f.largest_modulus) * wave.omega / (2 * std::numbers::pi);
  r.scalars = {wave.omega,   wave.omega_linear, wave.omega - wave.omega_linear, double(wave.harmonics),
               wave.residual, wave.tail,        f.stable ? 1.0 : 0.0,          f.largest_modulus,
               growth_rate,  w.theta,           double(wave.sites)};
  for (const auto& mu : f.multipliers) r.rows.insert(r.rows.end(), {mu.real(), mu.imag(), std::abs(mu)});
  r.status = PointStatus::ok;
  return r;
}

}  // namespace

std::shared_ptr<const TableSchema> wave_table(std::string_view kind) {
  std::vector<KeySchema> keys;
  for (const JobOption& o : jobs::wave::wave_options())
    if (sweep_option(o, step_of(kind))) keys.push_back(sweep_option_key(o));
  return std::make_shared<const TableSchema>(
      TableSchema{kind == "wave fate" ? "an exact travelling wave, its growth rates and what it becomes on a ring, as "
                                        "`lrchain wave fate`"
                  : kind == "wave standing"
                      ? "an exact standing wave and its Floquet multipliers on a ring, as `lrchain wave standing`"
                      : "an exact travelling wave and its Floquet-Bloch growth rates, as `lrchain wave stability`",
                  keys, std::nullopt});
}

std::vector<std::string> wave_scalar_names(std::string_view kind) {
  if (kind == "wave standing")
    return {"omega",  "omega_linear",    "omega_shift", "harmonics",  "residual",    "tail",
            "stable", "largest_modulus", "growth_rate", "ring_theta", "period_sites"};
  std::vector<std::string> n{"omega",       "omega_linear",     "omega_shift", "nls_omega_shift",
                                          "harmonics",   "residual",         "stable",      "largest_rate",
                                          "at_k",        "nls_largest_rate", "nls_k",       "unstable_bands",
                                          "h_tilde",     "focusing"};
  if (kind == "wave fate")
    n.insert(n.end(), {"fate", "broke_at", "predicted_breakup", "participation_end", "entropy_end",
                       "localized_kind", "bright_structures", "dark_structures", "dark_seen_fraction", "dark_width",
                       "dark_depth", "dark_frequency", "bright_frequency", "band_low", "band_high", "ring_theta",
                       "dark_from", "dark_until", "dark_stage_count", "dark_stage_width", "dark_stage_depth",
                       "bright_from", "bright_until", "bright_stage_count"});
  return n;
}

const std::vector<std::string>& wave_row_names(std::string_view kind) {
  static const std::vector<std::string> bands{"k_from", "k_to", "largest_rate", "at_k"}, multipliers{"re", "im", "modulus"};
  return kind == "wave standing" ? multipliers : bands;
}

std::string wave_rows_legend(std::string_view kind) {
  if (kind == "wave standing")
    return "one row per Floquet multiplier mu of the standing wave on the ring (fields x 2 x ring_sites of them), by "
           "decreasing modulus: Re mu, Im mu, |mu|";
  return "one row per band of perturbation wavenumbers K with growth (Re lambda above unstable_tolerance x omega): "
         "its ends, its largest rate and the K of it";
}

void check_wave_base(std::string_view kind, const Document& doc, const CheckedTable& root, const ModelSource* source) {
  const PointModel p = point_model(root, source);
  read_wave(kind, doc, root, p);
}

JobResult run_wave(std::string_view kind, const Document& doc, const CheckedTable& root, const ModelSource* source,
                   const std::atomic<bool>* stop) {
  const PointModel p = point_model(root, source);
  WaveConfig c = read_wave(kind, doc, root, p);
  c.stop = stop;
  if (c.step == jobs::wave::WaveStep::standing) return standing_point(c);
  const jobs::wave::WaveResult w = jobs::wave::run(c);
  JobResult r;
  if (w.ring_run_failed) {  // the wave exists: its ring run blew up (status blew_up) or drifted
    const bool blew_up = w.failure->find("blew up") != std::string::npos;
    r.status = blew_up ? PointStatus::blew_up : PointStatus::numerical_failure;
    r.reason = "the fate's ring run: " + *w.failure;
    return r;
  }
  if (w.failure || !w.stability) {
    r.status = PointStatus::numerical_failure;
    r.reason = fmt::format("no wave at amplitude {}: {}", w.failed_at.value_or(c.amplitude), w.failure.value_or("no stability"));
    return r;
  }
  const nlohmann::json j = jobs::wave::to_json(w);  // the command's numbers, NLS predictions included
  const auto& s = j.at("stability");
  const auto number = [](const nlohmann::json& x) { return x.is_null() ? no_value : x.get<double>(); };
  const auto& wave = w.waves.back();
  r.scalars = {wave.omega,
               wave.omega_linear,
               wave.omega - wave.omega_linear,
               number(j.at("waves").back().at("nls_omega_shift")),
               double(wave.harmonics),
               wave.residual,
               s.at("stable").get<bool>() ? 1.0 : 0.0,
               s.at("largest_rate").get<double>(),
               number(s.at("at_k")),
               number(s.at("nls_largest_rate")),
               number(s.at("nls_k")),
               double(s.at("bands").size()),
               number(j.at("nls").at("h_tilde")),
               j.at("nls").at("regime") == "focusing" ? 1.0 : 0.0};
  if (w.fate) {
    const auto& f = j.at("fate");
    if (w.fate->interrupted) {
      r.status = PointStatus::missing;
      r.reason = "interrupted";
      return r;
    }
    // localized_kind: 1 bright, 2 dark, 3 both (no value unless localized); the deepest dark structure at the end
    const auto& dark = w.fate->dark_end;
    const bool localized = w.fate->fate == sim::wave::WaveFate::localized;
    r.scalars.insert(r.scalars.end(), {double(int(w.fate->fate)), number(f.at("broke_at")), number(f.at("predicted_breakup")),
                                       w.fate->participation_end, w.fate->entropy_end,
                                       localized ? double(int(w.fate->kind)) : no_value,
                                       double(w.fate->bright_structures), double(w.fate->dark_structures),
                                       number(f.at("dark_seen_fraction")),
                                       dark.empty() ? no_value : dark.front().width,
                                       dark.empty() ? no_value : dark.front().depth,
                                       number(f.at("dark_frequency")), number(f.at("bright_frequency")),
                                       w.band[0], w.band[1], w.theta,
                                       // the stages (no value when none)
                                       number(f.at("dark_from")), number(f.at("dark_until")),
                                       number(f.at("dark_stage_count")), number(f.at("dark_stage_width")),
                                       number(f.at("dark_stage_depth")), number(f.at("bright_from")),
                                       number(f.at("bright_until")), number(f.at("bright_stage_count"))});
  }
  for (const auto& b : w.stability->bands) r.rows.insert(r.rows.end(), {b.k_from, b.k_to, b.largest_rate, b.at_k});
  r.status = PointStatus::ok;
  return r;
}

}  // namespace lrchain::jobs::sweep
