// Experiment 7 (Sec. 5.1): modulated acoustic wave eq:cimi on the periodic chain, long run with
// checkpoint/restart; outputs like Fig. 16.
#include "lrchain/sim/modulated_run.hpp"
#include "lrchain/provenance_json.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <initializer_list>
#include <fmt/format.h>

#include "lrchain/checked_number.hpp"
#include "lrchain/coefficients.hpp"
#include "lrchain/dispersion.hpp"
#include "lrchain/errors.hpp"
#include "lrchain/sim/checkpoint.hpp"
#include "lrchain/sim/displacement_lattice.hpp"
#include "lrchain/sim/integrator.hpp"
#include "lrchain/sim/energy.hpp"
#include "lrchain/sim/least_squares.hpp"
#include "lrchain/sim/observation.hpp"
#include "lrchain/sim/figure_format.hpp"
#include "lrchain/sim/output_files.hpp"
#include "restart.hpp"
#include "sampling_checks.hpp"
#include "run_json.hpp"

namespace lrchain::sim {

namespace {

constexpr std::int64_t max_samples = 1'000'000'000'000'000;  // far above any memory; no overflow

// Observation times k * every for k = first..: floor(t / every) (validated: no overflow).
std::int64_t grid_index(double t, double every, const std::string& parameter) {
  return checked_count(std::floor(t / every), parameter, 0, max_samples,
                       "samples (t-end / " + parameter + ")");
}

}  // namespace

std::vector<double> snapshot_times_in_run(const ModulatedRunConfig& c) {
  if (c.snapshot_times != default_modulated_snapshot_times()) return c.snapshot_times;
  std::vector<double> inside;
  for (double t : c.snapshot_times)
    if (t <= c.t_end) inside.push_back(t);
  return inside;
}

namespace {

// The sizes the run's memory and output grow with.
LatticeRunSizes run_sizes(const ModulatedRunConfig& c) {
  LatticeRunSizes s;
  s.sites = double(c.N);
  const double snapshots = double(snapshot_times_in_run(c).size());
  const double samples = double(grid_index(c.t_end, c.sample_every, "sample-every")) + 2;
  s.observations = samples + snapshots;
  s.series_columns = 5;
  s.spacetime_rows = samples;
  s.snapshots = snapshots;
  s.stepper = c.integrator.stepper;
  return s;
}

}  // namespace

ResourceEstimate estimate_resources(const ModulatedRunConfig& c) { return estimate_lattice_run(run_sizes(c)); }

void validate(const ModulatedRunConfig& c) {
  validate(c.params);
  if (c.N < 8) throw InvalidParameter("sites", "must be an integer >= 8");
  check_in_range(c.epsilon, modulation_amplitude_range);
  if (!(c.theta_waves > 0 && c.theta_waves < double(c.N)))
    throw InvalidParameter("theta-waves", "theta0 = theta_waves*pi/sites must lie in (0, pi)");
  if (!(c.b >= 0 && c.b < 1)) throw InvalidParameter("modulation-depth", "must be in [0, 1)");
  if (!(c.t_end > 0 && std::isfinite(c.t_end))) throw InvalidParameter("t-end", "must be a finite number > 0");
  validate_sampling({c.t_end, "t_end", false, c.sample_every, std::nullopt, c.checkpoint_every,
                     snapshot_times_in_run(c),
                     (c.checkpoint_every > 0 && !c.checkpoint_file.empty()) || !c.restart_file.empty(),
                     "snapshot_times", {{"speed-fit-start", c.speed_fit_start}, {"speed-fit-end", c.speed_fit_end}},
                     [&c](double t_end) {
                       ModulatedRunConfig longer = c;
                       longer.t_end = t_end;
                       return run_sizes(longer);
                     }, c.max_memory});
  if (c.dark_window < 1 || c.dark_window >= c.N) throw InvalidParameter("dark-window", "must be in [1, sites)");
  // (max e - min e)/mean e <= N for any energy density e >= 0 on N sites.
  if (!(c.contrast_threshold > 0 && c.contrast_threshold <= double(c.N)))
    throw InvalidParameter("contrast-threshold",
                           "must be in (0, sites]: the contrast (max e - min e)/mean e never exceeds the number of sites");
  checked_finite(c.speed_fit_start, "speed-fit-start");
  checked_finite(c.speed_fit_end, "speed-fit-end");
  if (!(c.speed_fit_end > c.speed_fit_start))
    throw InvalidParameter("speed-fit-end", "must exceed speed-fit-start (the fit window [speed_fit_start, speed_fit_end])");
  validate(c.integrator);
  const LatticeRunSizes sizes = run_sizes(c);  // also checks the sample counts
  validate_step_within_run(c.integrator, c.t_end);
  validate_step_count(c.integrator, c.t_end);
  const bool lattice = lattice_dominates(sizes);
  check_memory(estimate_lattice_run(sizes), c.max_memory, lattice ? "sites" : "sample-every",
               lattice ? "lower sites" : "lower t-end or raise sample-every");
}

// eq:cimi with omega = omega_-(theta0), theta0 = theta_waves pi / N.
State modulated_initial_state(const ModulatedRunConfig& c, double& omega, double& theta0) {
  const std::size_t N = std::size_t(c.N);
  theta0 = c.theta_waves * M_PI / double(c.N);
  omega = dispersion_omega(c.params, Branch::acoustic, theta0);
  const double ratio = c.params.kappa / (c.params.kappa - c.params.rho * omega * omega);
  StateLayout L{c.N};
  State s(L.size());
  for (std::size_t i = 0; i < N; ++i) {
    const double n = double(i), mod = 1 + c.b * std::cos(2 * n * M_PI / double(c.N));
    const double u = c.epsilon * std::sin(theta0 * n) * mod;
    const double ud = -c.epsilon * omega * std::cos(theta0 * n) * mod;
    L.primary(s)[i] = u;
    L.secondary(s)[i] = ratio * u;
    L.primary_rate(s)[i] = ud;
    L.secondary_rate(s)[i] = ratio * ud;
  }
  return s;
}

namespace {

// Periodic running mean of e over w sites (centred), into m.
void running_mean(const std::vector<double>& e, long w, std::vector<double>& m) {
  const long N = long(e.size()), h = w / 2;
  for (long i = 0; i < N; ++i) {
    double s = 0;
    for (long k = -h; k < -h + w; ++k) s += e[std::size_t(((i + k) % N + N) % N)];
    m[std::size_t(i)] = s / double(w);
  }
}

}  // namespace

ModulatedRunResult run_modulated(const ModulatedRunConfig& c, const RunControl& control) {
  validate(c);
  ModulatedRunResult result;
  auto& S = result.summary;
  const std::size_t N = std::size_t(c.N);
  State s = modulated_initial_state(c, S.omega, S.theta0);
  S.group_velocity = coefficients(c.params, Branch::acoustic, S.theta0).group_velocity;
  DisplacementBoundary boundary;
  boundary.periodic = true;
  const DisplacementLattice chain(c.params, N, boundary);
  const auto& L = chain.layout();
  S.energy0 = chain.total_energy(s, 0);  // of eq:cimi, also on restart

  // Observation times: samples on the grid k*sample_every and the snapshot times. Checkpoints are
  // written at the step boundaries that reach each multiple of checkpoint_every (no extra times).
  // The number of samples is bounded by validate (run_sizes).
  std::vector<double> times{0.0};
  for (std::int64_t k = 1; double(k) * c.sample_every < c.t_end; ++k) times.push_back(double(k) * c.sample_every);
  times.push_back(c.t_end);
  std::vector<double> snap_times;
  for (double ts : snapshot_times_in_run(c))  // later ones belong to a continuation
    if (ts <= c.t_end) snap_times.push_back(ts);
  times = merge_observation_times(std::move(times), snap_times, c.t_end);

  auto& rec = result.record;
  rec.series.names = {"t", "energy", "contrast", "dark_centre", "dark_unwrapped"};
  rec.fields.resize(1);
  rec.fields[0].quantity = "energy_density";
  rec.fields[0].first_label = 0;
  rec.fields[0].sites = N;
  std::vector<double> e(N), m(N), scratch(N + 1);
  double prev_centre = -1, unwrapped = 0, next_row = 0, first = 1;

  // What defines the trajectory and its record; a restart must match every item.
  TrajectoryIdentity identity = base_identity("modulated", c.params, c.integrator);
  identity.add("N", c.N, {"sites"});
  identity.add("epsilon", c.epsilon);
  identity.add("theta_waves", c.theta_waves);
  identity.add("b", c.b, {"modulation_depth"});
  identity.add("sample_every", c.sample_every);
  identity.add("dark_window", c.dark_window);
  identity.add("contrast_threshold", c.contrast_threshold);
  identity.add_state_hash("initial_state", s);

  bool skip_first = false;
  double resume_step = 0;
  CheckpointSink sink;
  sink.file = c.checkpoint_file;
  sink.identity = identity.text();
  sink.t_end = c.t_end;
  sink.at_end = c.checkpoint_every > 0;
  if (!c.restart_file.empty()) {
    double instability_found = 0, instability_time = 0;  // the optional, as two numbers
    const Resumption r = resume_from_checkpoint(
        c.restart_file, identity, "modulated", N, c.t_end, s, rec,
        {{"initial_contrast", &S.initial_contrast}, {"max_energy_drift", &S.max_energy_drift},
         {"instability_found", &instability_found}, {"instability_time", &instability_time},
         {"previous_centre", &prev_centre}, {"unwrapped_centre", &unwrapped},
         {"next_spacetime_row", &next_row}, {"first", &first}},
        sink, times);
    if (instability_found != 0) S.instability_time = instability_time;
    skip_first = true;  // the checkpoint's record already holds the observation at its time
    resume_step = r.next_step;
    S.t_start = r.t;
  }
  sink.rhythm = CheckpointRhythm(c.checkpoint_every, S.t_start);
  SpaceTime& field = rec.fields[0];  // (after a restart, the checkpoint's)
  auto near = [&](double a, double b) { return std::abs(a - b) <= 1e-9 * c.t_end; };

  auto observe = [&](const State& st, double t) {
    if (skip_first) {
      skip_first = false;
      return true;
    }
    energy_density(chain, st, t, e, scratch);
    running_mean(e, c.dark_window, m);
    const auto [mn, mx] = std::minmax_element(m.begin(), m.end());
    double mean = 0;
    for (double v : m) mean += v;
    mean /= double(N);
    const double contrast = (*mx - *mn) / mean;
    const double centre = double(mn - m.begin());
    if (prev_centre >= 0) {
      double d = centre - prev_centre;
      if (d > double(N) / 2) d -= double(N);
      if (d < -double(N) / 2) d += double(N);
      unwrapped += d;
    } else {
      unwrapped = centre;
    }
    prev_centre = centre;
    const double energy = chain.total_energy(st, t);
    if (first != 0) S.initial_contrast = contrast;
    first = 0;
    S.max_energy_drift = std::max(S.max_energy_drift, std::abs(energy - S.energy0) / S.energy0);
    if (!S.instability_time && contrast > c.contrast_threshold) S.instability_time = t;
    rec.series.data.insert(rec.series.data.end(), {t, energy, contrast, centre, unwrapped});
    if (t >= next_row - 1e-9 * c.t_end) {
      field.times.push_back(t);
      for (double v : e) field.values.push_back(float(v));
      next_row += c.sample_every;
    }
    for (double ts : snap_times) {
      if (!near(ts, t)) continue;
      rec.snapshots.push_back(displacement_snapshot(L, st, e, t, fmt::format("t{:.0f}", t), 0));
      break;
    }
    if (control.on_sample)
      control.on_sample({t, 0, {L.primary(st), std::size_t(N)}, {L.secondary(st), std::size_t(N)}, 0,
                         {e.data(), std::size_t(N)}});
    if (control.progress) control.progress((t - S.t_start) / (c.t_end - S.t_start));
    return true;
  };
  // At step boundaries: periodic and final checkpoints; on an interrupt, a checkpoint and stop.
  auto at_boundary = [&](const State& st, double t, double next_step, const IntegrationStats& work) {
    const bool stop = control.stop_requested() && t < times.back();  // at the end: just finish
    if (stop || sink.due(t))
      sink.write(st, t, next_step, work, rec,
                 {{"initial_contrast", S.initial_contrast}, {"max_energy_drift", S.max_energy_drift},
                  {"instability_found", S.instability_time ? 1.0 : 0.0},
                  {"instability_time", S.instability_time.value_or(0.0)}, {"previous_centre", prev_centre},
                  {"unwrapped_centre", unwrapped}, {"next_spacetime_row", next_row}, {"first", first}});
    return !stop;
  };

  const auto start = std::chrono::steady_clock::now();
  S.stats = integrate_observed(chain, s, times, observe, c.integrator, at_boundary, resume_step, control.stop);
  S.solve_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  S.stats.steps += static_cast<Index>(sink.base_steps);
  S.stats.rhs_evaluations += static_cast<Index>(sink.base_rhs_evaluations);
  S.checkpoints_written = sink.written;
  S.last_checkpoint_time = sink.last_time;
  S.t_end = S.stats.t_reached;
  S.interrupted = S.stats.stopped;
  S.blew_up = S.stats.blew_up;
  S.blow_up = locate_blow_up(S.stats, N, 0);
  // Dark-breather speed: slope of the series' unwrapped minimum position over the fit window.
  std::vector<double> fit_t, fit_x;
  for (Index r = 0; r < rec.series.rows(); ++r) {
    const double t = rec.series.at(r, 0);
    if (t >= c.speed_fit_start - 1e-9 && t <= c.speed_fit_end + 1e-9) {
      fit_t.push_back(t);
      fit_x.push_back(rec.series.at(r, 4));
    }
  }
  S.dark_samples = long(fit_t.size());
  S.dark_speed = std::abs(least_squares_slope(fit_t, fit_x));
  return result;
}

nlohmann::json to_json(const ModulatedRunConfig& c, const ModulatedRunSummary& s) {
  nlohmann::json j;
  j["experiment"] = "modulated";
  j["provenance"] = provenance_json();
  j["name"] = c.name;
  j["model"] = model_json(resonant_chain_model(c.params));
  j["sites"] = c.N;
  j["initial"] = {{"epsilon", c.epsilon}, {"theta0", s.theta0}, {"omega", s.omega}, {"modulation_depth", c.b}};
  j["integrator"] = integrator_json(c.integrator);
  j["group_velocity"] = s.group_velocity;
  j["t_start"] = s.t_start;
  j["initial_contrast"] = s.initial_contrast;
  j["contrast_threshold"] = c.contrast_threshold;
  j["instability_time"] = s.instability_time ? nlohmann::json(*s.instability_time) : nlohmann::json(nullptr);
  j["dark_speed"] = s.dark_samples >= 2 ? nlohmann::json(s.dark_speed) : nlohmann::json(nullptr);  // fit needs 2
  j["dark_speed_fit"] = {c.speed_fit_start, c.speed_fit_end};
  j["dark_samples"] = s.dark_samples;
  j["energy0"] = s.energy0;
  j["max_relative_energy_drift"] = s.max_energy_drift;
  j["checkpoints_written"] = s.checkpoints_written;
  if (!c.checkpoint_file.empty()) j["checkpoint_file"] = c.checkpoint_file;
  add_run_status(j, s.t_end, s.interrupted, s.blew_up, s.stats, s.solve_seconds, s.blow_up);
  return j;
}

namespace {

std::string modulated_energy_script(const ModulatedRunResult& r, const nlohmann::json& summary) {
  double sum = 0, count = 0;
  for (const auto& f : r.record.fields)
    for (float v : f.values) { sum += v; count += 1; }
  const double emean = count > 0 && sum > 0 ? sum / count : 1;
  const double threshold = summary.value("contrast_threshold", 0.2);
  // The onset of the modulational instability: the first time the contrast exceeds the threshold.
  std::string onset;
  if (summary.contains("instability_time") && summary["instability_time"].is_number())
    onset = fmt::format("set arrow from {0}, graph 0 to {0}, graph 1 nohead dt 3 lw 1.5 lc rgb 'dark-green' front\n"
                        "set label 'onset t = {0:.0f}' at {0}, graph 0.93 offset 0.5,0 tc rgb 'dark-green' front\n",
                        summary["instability_time"].get<double>());
  return fmt::format(R"GP(# Energy density e_n(t) (eq. (40)) on the periodic chain (Fig. 16 bottom right), and the
# contrast (max-min)/mean of the running-mean e_n with the position of its minimum (dark-breather centre);
# dashed: the contrast threshold, dotted: the onset time (first contrast above it).
if (!exists("outfile")) outfile = 'energy.png'
set terminal pngcairo size 1400,700 font ",11"
set output outfile
set multiplot layout 1,2
set xlabel "site n"
set ylabel "t (dimensionless)"
{}
set cblabel "energy density e_{{n}}, eq. (40)"
set rmargin at screen 0.40
set cbrange [0:{:.3e}]
set autoscale fix
plot 'energy_density_spacetime.bin' binary matrix {}with image notitle
unset cblabel
set lmargin at screen 0.57
set rmargin at screen 0.92
set autoscale
set datafile separator ","
set xlabel "t (dimensionless)"
set ylabel "contrast (max e - min e)/mean e"
set y2label "site of the minimum of e_{{n}}"
set y2tics
set ytics nomirror
set yrange [0:*]
set offsets 0, 0, graph 0.12, 0
set key top left opaque box
{}plot 'series.csv' using 1:3 skip 1 with lines lw 1.2 title "contrast", \
     {:g} with lines dt 2 lw 1.5 lc rgb "black" title "threshold {:g}", \
     'series.csv' using 1:4 skip 1 axes x1y2 with points pt 7 ps 0.2 lc rgb "red" title "min-e site"
unset multiplot
)GP",
                     viridis_palette, 2 * emean,
                     r.record.fields.empty() ? "" : image_every(r.record.fields.front()), onset, threshold, threshold);
}

std::string modulated_snapshots_script(const ModulatedRunResult& r) {
  std::string body;
  for (const auto& s : r.record.snapshots)
    body += fmt::format("set title \"t = {:.0f}\"\nplot 'snapshot_{}.csv' using 1:4 skip 1 with linespoints pt 7 ps 0.3 lw 0.8 notitle\n",
                        s.t, s.tag);
  const std::size_t k = std::max<std::size_t>(1, r.record.snapshots.size());
  return fmt::format(R"GP(# Bead velocities du_n/dt at the snapshot times (Fig. 16).
if (!exists("outfile")) outfile = 'snapshots.png'
set terminal pngcairo size 1400,{} font ",11"
set output outfile
set datafile separator ","
set multiplot layout {},1
set xlabel "site n"
set ylabel "bead velocity du_n/dt"
{}unset multiplot
)GP",
                     330 * k, k, body);
}

}  // namespace

std::vector<std::string> write_modulated_outputs(const std::string& dir, const ModulatedRunResult& r,
                                                 const nlohmann::json& summary, bool draw_figures) {
  std::vector<FigureScript> figures = {{"energy.gp", modulated_energy_script(r, summary), "energy.png"}};
  if (!r.record.snapshots.empty())
    figures.push_back({"snapshots.gp", modulated_snapshots_script(r), "snapshots.png"});
  return write_run_outputs(dir, r.record, summary.dump(2), figures, draw_figures);
}

}  // namespace lrchain::sim
