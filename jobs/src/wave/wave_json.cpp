// to_json(WaveResult): the summary `lrchain wave ...` prints and summary.json holds (wave_job.hpp).
#include <cmath>
#include <numbers>

#include "lrchain/jobs/wave_job.hpp"
#include "lrchain/model_json.hpp"
#include "lrchain/provenance_json.hpp"
#include "lrchain/sim/wave/wave_nls.hpp"
#include "wave_standing.hpp"

namespace lrchain::jobs::wave {

using nlohmann::json;

namespace {

json number_or_null(double x) { return std::isfinite(x) ? json(x) : json(nullptr); }

const char* step_name(WaveStep s) {
  switch (s) {
    case WaveStep::solve: return "solve";
    case WaveStep::branch: return "continue";
    case WaveStep::stability: return "stability";
    case WaveStep::fate: return "fate";
    case WaveStep::standing: return "standing";
  }
  return "";
}

json wave_json(const sim::wave::TravellingWave& w, const NlsCoefficients& nls) {
  return {{"amplitude", w.amplitude},
          {"omega", w.omega},
          {"omega_shift", w.omega - w.omega_linear},
          {"nls_omega_shift", number_or_null(sim::wave::nls_frequency_shift(nls.h, w.amplitude))},
          {"harmonics", w.harmonics},
          {"tail", w.tail},
          {"residual", w.residual},
          {"newton_steps", w.newton_steps},
          {"least_contact_overlap", w.least_contact_overlap ? json(*w.least_contact_overlap) : json(nullptr)},
          {"nearest_harmonic_resonance",
           w.resonance_harmonic > 0 ? json{{"harmonic", w.resonance_harmonic}, {"distance", w.resonance_distance}}
                                    : json(nullptr)}};
}

}  // namespace

json to_json(const WaveResult& r) {
  const WaveConfig& c = r.config;
  json j;
  j["model"] = model_json(*c.model);
  j["step"] = step_name(c.step);
  j["branch"] = r.branch;
  j["theta"] = r.theta;  // the wave's: for fate and standing the ring's nearest 2 pi j / N
  j["requested_theta"] = c.theta;
  j["options"] = {{"initial_harmonics", c.initial_harmonics}, {"max_harmonics", c.max_harmonics},
                  {"tail_tolerance", c.tail_tolerance},       {"tolerance", c.tolerance},
                  {"max_iterations", c.max_iterations}};
  if (c.step == WaveStep::branch) j["options"]["amplitudes"] = c.amplitudes;
  else j["options"].update({{"amplitude", c.amplitude}, {"ramp", c.ramp}});
  if (c.step == WaveStep::standing) j["options"]["ring_sites"] = c.ring_sites;
  if (c.step == WaveStep::stability || c.step == WaveStep::fate)  // fate runs the stability step first
    j["options"].update({{"k_points", c.k_points}, {"unstable_tolerance", c.unstable_tolerance}});
  j["linear"] = {{"omega", r.mode.omega}};
  j["nls"] = {{"omega", r.nls.omega},         {"group_velocity", r.nls.group_velocity},
              {"curvature", r.nls.curvature}, {"h", number_or_null(r.nls.h)},
              {"h_tilde", number_or_null(r.nls.h_tilde)}, {"regime", std::string(to_string(r.nls.regime))}};
  j["translation_invariant"] = r.waves.empty() ? json(nullptr) : json(r.waves.front().translation_invariant);
  json waves = json::array();
  for (const auto& w : r.waves) waves.push_back(wave_json(w, r.nls));
  j["waves"] = waves;
  if (c.step != WaveStep::branch && c.step != WaveStep::standing && !r.failure) {
    const auto& w = r.waves.back();
    j["omega"] = w.omega;
    j["harmonics"] = w.harmonics;
    j["residual"] = w.residual;
    const Index points = 2 * w.harmonics + 1, fields = Index(r.mode.kernel.size());
    json xi = json::array(), fields_json = json::object();
    for (Index i = 0; i < points; ++i) xi.push_back(2 * std::numbers::pi * double(i) / double(points));
    for (Index f = 0; f < fields; ++f) {
      json values = json::array();
      for (Index i = 0; i < points; ++i) values.push_back(w.profile(f * points + i));
      fields_json["u" + std::to_string(f)] = values;
    }
    j["profile"] = {{"xi", xi}, {"fields", fields_json}};
  }
  if (r.stability) {
    const auto& s = *r.stability;
    const double U = c.amplitude;
    json nls_rate = json::array(), bands = json::array();
    for (double K : s.k) nls_rate.push_back(sim::wave::nls_growth_rate(r.nls.curvature, r.nls.h_tilde, U, K));
    for (const auto& b : s.bands)
      bands.push_back({{"k_from", b.k_from}, {"k_to", b.k_to}, {"largest_rate", b.largest_rate}, {"at_k", b.at_k}});
    const bool focusing = r.nls.regime == Regime::focusing;
    j["stability"] = {{"stable", s.stable},
                      {"largest_rate", s.largest_rate},
                      {"at_k", s.stable ? json(nullptr) : json(s.at_k)},
                      {"bands", bands},
                      {"nls_largest_rate", sim::wave::nls_largest_growth_rate(r.nls.curvature, r.nls.h_tilde, U)},
                      {"nls_k", focusing ? json(sim::wave::nls_most_unstable_k(r.nls.curvature, r.nls.h_tilde, U)) : json(nullptr)},
                      {"k", s.k},
                      {"growth_rate", s.growth_rate},
                      {"nls_growth_rate", nls_rate}};
  }
  if (r.fate) {
    const auto& f = *r.fate;
    const double rate = r.ring_growth.rate;  // among the K the ring holds
    json dark_end = json::array();
    for (const auto& d : f.dark_end)
      dark_end.push_back({{"centre", d.centre}, {"width", d.width}, {"depth", d.depth}});
    j["fate"] = {{"fate", std::string(sim::wave::to_string(f.fate))},
                 {"ring_sites", c.ring_sites},
                 {"ring_theta", r.theta},
                 {"noise", c.noise},
                 {"modulation", c.modulation},
                 {"seed", c.seed},
                 {"periods", f.t.empty() ? 0.0 : std::round(f.t.back() * r.waves.back().omega / (2 * std::numbers::pi))},
                 {"steps_per_period", c.steps_per_period},
                 {"broke_at", f.broke_at < 0 ? json(nullptr) : json(f.broke_at)},
                 // the noise grows e^{rate t} from c.noise to the breakup deviation (the Floquet-Bloch prediction)
                 {"predicted_breakup", rate > 0 && c.noise > 0 ? json(std::log(sim::wave::kBrokenDeviation / c.noise) / rate)
                                                               : json(nullptr)},
                 {"ring_largest_rate", rate},
                 {"ring_at_k", rate > 0 ? json(r.ring_growth.at_k) : json(nullptr)},
                 {"participation_end", f.participation_end},
                 {"entropy_end", f.entropy_end},
                 {"localized_kind", f.fate == sim::wave::WaveFate::localized ? json(std::string(sim::wave::to_string(f.kind)))
                                                                             : json(nullptr)},
                 {"bright_structures", f.bright_structures},
                 {"dark_structures", f.dark_structures},
                 {"dark_seen_fraction", f.broke_at < 0 ? json(nullptr) : json(f.dark_seen_fraction)},
                 {"dark_end", dark_end},
                 // the stages: first and last time of structures held in most of a kStagePeriods-sample window
                 {"deviation_of", f.strain_deviation ? "strain" : "displacement"},
                 {"stage_window", sim::wave::kStagePeriods},
                 {"dark_from", number_or_null(f.dark_stage.from)},
                 {"dark_until", number_or_null(f.dark_stage.until)},
                 {"dark_stage_count", f.dark_stage.found() ? json(f.dark_stage.count) : json(nullptr)},
                 {"dark_stage_width", number_or_null(f.dark_stage.width)},
                 {"dark_stage_depth", number_or_null(f.dark_stage.depth)},
                 {"bright_from", number_or_null(f.bright_stage.from)},
                 {"bright_until", number_or_null(f.bright_stage.until)},
                 {"bright_stage_count", f.bright_stage.found() ? json(f.bright_stage.count) : json(nullptr)},
                 {"dark_background_spread", number_or_null(f.dark_background_spread)},
                 {"envelope_window", f.envelope_window},
                 {"dark_frequency", number_or_null(f.dark_frequency)},
                 {"dark_site", f.dark_site < 0 ? json(nullptr) : json(f.dark_site)},
                 {"bright_frequency", number_or_null(f.bright_frequency)},
                 {"bright_site", f.bright_site < 0 ? json(nullptr) : json(f.bright_site)},
                 {"band", {{"low", r.band[0]}, {"high", r.band[1]}}},
                 {"max_relative_energy_drift", f.max_relative_energy_drift},
                 {"interrupted", f.interrupted},
                 {"thresholds", {{"broken_deviation", sim::wave::kBrokenDeviation},
                                 {"localized_participation", sim::wave::kLocalizedParticipation},
                                 {"disordered_entropy", sim::wave::kDisorderedEntropy},
                                 {"dark_depth", sim::wave::kDarkDepth},
                                 {"dark_width_share", sim::wave::kDarkWidthShare},
                                 {"dark_background_spread", sim::wave::kDarkBackgroundSpread}}},
                 {"t", f.t},
                 {"deviation", f.deviation},
                 {"participation", f.participation},
                 {"entropy", f.entropy},
                 {"dark", f.dark},
                 {"bright", f.bright},
                 {"energy_density", f.energy_density}};
  }
  if (c.step == WaveStep::standing) j["standing"] = standing_json(r);
  j["failure"] = r.failure ? json(*r.failure) : json(nullptr);
  j["failed_at"] = r.failed_at ? json(*r.failed_at) : json(nullptr);
  j["seconds"] = r.seconds;
  j["provenance"] = provenance_json();
  return j;
}

}  // namespace lrchain::jobs::wave
