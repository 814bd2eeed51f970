// Experiment 7 (Sec. 5.1): modulated acoustic wave eq:cimi on the periodic chain, long run with
// checkpoint/restart; outputs like Fig. 16.
#include "lrchain/sim/modulated_run.hpp"

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
#include "lrchain/sim/displacement_lattice.hpp"
#include "lrchain/sim/integrator.hpp"
#include "lrchain/sim/energy.hpp"
#include "lrchain/sim/least_squares.hpp"
#include "observation.hpp"
#include "checkpointing.hpp"
#include "sampling_checks.hpp"

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
  // (the name is also the message's text "samples (t-end / sample-every)": the command's spelling)
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
    throw InvalidParameter("theta_waves", "theta0 = theta_waves*pi/sites must lie in (0, pi)");
  if (!(c.b >= 0 && c.b < 1)) throw InvalidParameter("modulation_depth", "must be in [0, 1)");
  if (!(c.t_end > 0 && std::isfinite(c.t_end))) throw InvalidParameter("t_end", "must be a finite number > 0");
  validate_sampling({c.t_end, "t_end", false, c.sample_every, std::nullopt, c.checkpoint_every,
                     snapshot_times_in_run(c),
                     (c.checkpoint_every > 0 && !c.checkpoint_file.empty()) || !c.restart_file.empty(),
                     "snapshot_times", {{"speed_fit_start", c.speed_fit_start}, {"speed_fit_end", c.speed_fit_end}},
                     [&c](double t_end) {
                       ModulatedRunConfig longer = c;
                       longer.t_end = t_end;
                       return run_sizes(longer);
                     }, c.max_memory});
  if (c.dark_window < 1 || c.dark_window >= c.N) throw InvalidParameter("dark_window", "must be in [1, sites)");
  // (max e - min e)/mean e <= N for any energy density e >= 0 on N sites.
  if (!(c.contrast_threshold > 0 && c.contrast_threshold <= double(c.N)))
    throw InvalidParameter("contrast_threshold",
                           "must be in (0, sites]: the contrast (max e - min e)/mean e never exceeds the number of sites");
  checked_finite(c.speed_fit_start, "speed_fit_start");
  checked_finite(c.speed_fit_end, "speed_fit_end");
  if (!(c.speed_fit_end > c.speed_fit_start))
    throw InvalidParameter("speed_fit_end", "must exceed speed-fit-start (the fit window [speed_fit_start, speed_fit_end])");
  validate(c.integrator);
  const LatticeRunSizes sizes = run_sizes(c);  // also checks the sample counts
  validate_step_within_run(c.integrator, c.t_end);
  validate_step_count(c.integrator, c.t_end);
  const bool lattice = lattice_dominates(sizes);
  check_memory(estimate_lattice_run(sizes), c.max_memory, lattice ? "sites" : "sample_every",
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
  require_checkpoint_store(control, c.checkpoint_file, c.restart_file);
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
  sink.store = &control.checkpoints;
  sink.identity = &identity;
  sink.t_end = c.t_end;
  sink.at_end = c.checkpoint_every > 0;
  if (control.checkpoints.load) {
    double instability_found = 0, instability_time = 0;  // the optional, as two numbers
    const Resumption r = resume_from_checkpoint(
        control.checkpoints, identity, "modulated", N, c.t_end, s, rec,
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

}  // namespace lrchain::sim
