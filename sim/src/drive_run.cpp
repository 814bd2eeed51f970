// Experiment 6 (Sec. 4.3): boundary-driven chain, clamped far end; outputs like Figs. 14, 15.
#include "lrchain/sim/drive_run.hpp"

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

// Sample intervals floor(t_end / sample_every) of the run (validated: no overflow).
// (the name is also the message's text "samples (t-end / sample-every)": the command's spelling)
Index sample_intervals(const DriveRunConfig& c) { return sim::sample_intervals(c.t_end, c.sample_every, "t-end"); }

}  // namespace

std::vector<double> snapshot_times_in_run(const DriveRunConfig& c) {
  return times_inside_run(c.snapshot_times, default_drive_snapshot_times(), c.t_end);
}

namespace {

// InvalidParameter("omega0") unless omega0 lies in the optical band (omega_+(0), omega_+(pi)] (eq:disp1d).
void check_optical_band(const Params& p, double omega0) {
  const double wa = dispersion_omega(p, Branch::optical, 0.0), wb = dispersion_omega(p, Branch::optical, M_PI);
  if (!(omega0 > wa && omega0 <= wb))
    throw InvalidParameter("omega0", fmt::format("must lie in the optical band ({:.6g}, {:.6g}]", wa, wb));
}

// The sizes the run's memory and output grow with.
LatticeRunSizes run_sizes(const DriveRunConfig& c) {
  return sampled_run_sizes(double(c.beads), c.t_end, c.sample_every, c.spacetime_every,
                           double(snapshot_times_in_run(c).size()), c.integrator.stepper, "t-end");
}

}  // namespace

ResourceEstimate estimate_resources(const DriveRunConfig& c) { return estimate_lattice_run(run_sizes(c)); }

void validate(const DriveRunConfig& c) {
  validate(c.params);
  if (c.beads < 10) throw InvalidParameter("sites", "must be an integer >= 10");
  check_drive_amplitude(c.amplitude, c.params.delta0);
  if (!(c.omega0 > 0 && std::isfinite(c.omega0))) throw InvalidParameter("omega0", "must be a finite number > 0");
  check_optical_band(c.params, c.omega0);
  if (!(c.ramp_rate > 0 && c.ramp_rate <= c.omega0))
    throw InvalidParameter("ramp_rate", "must be in (0, omega0]: the envelope chi(t) varies slowly against the carrier");
  if (!(c.t_end > 0 && std::isfinite(c.t_end))) throw InvalidParameter("t_end", "must be a finite number > 0");
  validate_sampling({c.t_end, "t_end", false, c.sample_every, c.spacetime_every, c.checkpoint_every,
                     snapshot_times_in_run(c),
                     (c.checkpoint_at_end && !c.checkpoint_file.empty()) || !c.restart_file.empty(),
                     "snapshot_times",
                     {{"switch_off_time", c.t_m}, {"front_fit_start", c.front_fit_start}, {"front_fit_end", c.front_fit_end}},
                     [&c](double t_end) {
                       DriveRunConfig longer = c;
                       longer.t_end = t_end;
                       return run_sizes(longer);
                     }, c.max_memory});
  if (!(c.front_fraction > 0 && c.front_fraction < 1))
    throw InvalidParameter("front_fraction", "must be in (0, 1)");
  if (!(c.t_m >= 0 && std::isfinite(c.t_m)))
    throw InvalidParameter("switch_off_time", "must be a finite number >= 0 (the time chi(t) starts to ramp down)");
  checked_finite(c.front_fit_start, "front_fit_start");
  checked_finite(c.front_fit_end, "front_fit_end");
  if (!(c.front_fit_end > c.front_fit_start))
    throw InvalidParameter("front_fit_end", "must exceed front-fit-start (the front-speed fit window "
                                            "[front_fit_start, front_fit_end])");
  validate(c.integrator);
  validate_step_within_run(c.integrator, c.t_end);
  if (is_symplectic(c.integrator.stepper))
    throw InvalidParameter("stepper", "the driven chain is not autonomous: use rkf78 or dopri5");
  const LatticeRunSizes sizes = run_sizes(c);  // also checks the sample counts
  const bool lattice = lattice_dominates(sizes);
  check_memory(estimate_lattice_run(sizes), c.max_memory, lattice ? "sites" : "t_end",
               lattice ? "lower sites" : "lower t-end or raise sample-every and spacetime-every");
}

// chi(t) = tanh(r t) (1 - tanh(r (t - t_m))) / 2 (Sec. 4.3).
double drive_envelope(double t, double r, double t_m) {
  return std::tanh(r * t) * (1 - std::tanh(r * (t - t_m))) / 2;
}

namespace {

// theta in (0, pi] with omega_+(theta) = omega0 (eq:disp1d; omega_+ increases on [0, pi]).
double optical_wavenumber(const Params& p, double omega0) {
  check_optical_band(p, omega0);
  double a = 0, b = M_PI;
  for (int k = 0; k < 200 && b - a > 1e-15; ++k) {
    const double m = 0.5 * (a + b);
    (dispersion_omega(p, Branch::optical, m) < omega0 ? a : b) = m;
  }
  return 0.5 * (a + b);
}

// Number of sites carrying the energy: (sum e)^2 / sum e^2.
double participation(const std::vector<double>& e) {
  double s = 0, s2 = 0;
  for (double v : e) { s += v; s2 += v * v; }
  return s2 > 0 ? s * s / s2 : 0;
}

// Local maxima of the 3-site running mean of e above `fraction` of its maximum.
long count_peaks(const std::vector<double>& e, double fraction) {
  const std::size_t n = e.size();
  if (n < 5) return 0;
  std::vector<double> m(n, 0);
  for (std::size_t i = 1; i + 1 < n; ++i) m[i] = (e[i - 1] + e[i] + e[i + 1]) / 3;
  const double top = *std::max_element(m.begin(), m.end());
  long peaks = 0;
  for (std::size_t i = 2; i + 2 < n; ++i)
    if (m[i] > fraction * top && m[i] >= m[i - 1] && m[i] > m[i + 1] && m[i] >= m[i - 2] &&
        m[i] > m[i + 2])
      ++peaks;
  return peaks;
}

}  // namespace

DriveRunResult run_drive(const DriveRunConfig& c, const RunControl& control) {
  validate(c);
  require_checkpoint_store(control, c.checkpoint_file, c.restart_file);
  DriveRunResult result;
  auto& S = result.summary;
  S.theta = optical_wavenumber(c.params, c.omega0);
  S.group_velocity = coefficients(c.params, Branch::optical, S.theta).group_velocity;

  const std::size_t beads = std::size_t(c.beads);
  DisplacementBoundary boundary;
  boundary.left.kind = EndKind::prescribed;
  boundary.left.motion = [A = c.amplitude, w = c.omega0, r = c.ramp_rate, tm = c.t_m](double t) {
    return A * std::sin(w * t) * drive_envelope(t, r, tm);
  };
  boundary.right.kind = EndKind::clamped;
  const DisplacementLattice chain(c.params, beads, boundary);
  const auto& L = chain.layout();
  State s(L.size(), 0.0);  // chain at rest

  std::vector<double> times;
  const Index samples = sample_intervals(c);
  times.reserve(static_cast<std::size_t>(samples) + 2);
  for (Index k = 0; k <= samples; ++k) times.push_back(double(k) * c.sample_every);
  if (c.t_end - times.back() > 1e-9 * c.t_end) times.push_back(c.t_end);
  std::vector<double> snap_times;
  for (double ts : snapshot_times_in_run(c))  // later ones belong to a continuation
    if (ts <= c.t_end * (1 + 1e-12)) snap_times.push_back(std::min(ts, c.t_end));
  times = merge_observation_times(std::move(times), snap_times, c.t_end);

  auto& rec = result.record;
  rec.series.names = {"t", "energy", "front", "participation", "u0"};
  rec.fields.resize(1);
  rec.fields[0].quantity = "energy_density";
  rec.fields[0].first_label = 1;
  rec.fields[0].sites = beads;
  std::vector<double> e(beads), scratch(beads + 1);
  double next_st = 0, final_peaks = 0;

  // What defines the trajectory and its record; a restart must match every item.
  TrajectoryIdentity identity = base_identity("drive", c.params, c.integrator);
  identity.add("beads", c.beads, {"sites"});
  identity.add("amplitude", c.amplitude);
  identity.add("omega0", c.omega0);
  identity.add("ramp_rate", c.ramp_rate);
  identity.add("t_m", c.t_m, {"switch_off_time"});
  identity.add("sample_every", c.sample_every);
  identity.add("spacetime_every", c.spacetime_every);
  identity.add("front_fraction", c.front_fraction);
  identity.add_state_hash("initial_state", s);

  bool skip_first = false;
  double resume_step = 0;
  CheckpointSink sink;
  sink.store = &control.checkpoints;
  sink.identity = &identity;
  sink.t_end = c.t_end;
  sink.at_end = c.checkpoint_at_end;
  if (control.checkpoints.load) {
    const Resumption r = resume_from_checkpoint(
        control.checkpoints, identity, "drive", beads, c.t_end, s, rec,
        {{"max_energy", &S.max_energy}, {"max_participation", &S.max_participation},
         {"final_energy", &S.final_energy}, {"final_participation", &S.final_participation},
         {"final_peaks", &final_peaks}, {"next_spacetime_row", &next_st}},
        sink, times);
    skip_first = true;  // the checkpoint's record already holds the observation at its time
    resume_step = r.next_step;
    S.t_start = r.t;
  }
  sink.rhythm = CheckpointRhythm(c.checkpoint_every, S.t_start);
  SpaceTime& field = rec.fields[0];  // (after a restart, the checkpoint's)

  auto observe = [&](const State& st, double t) {
    if (skip_first) {
      skip_first = false;
      return true;
    }
    energy_density(chain, st, t, e, scratch);
    const double emax = *std::max_element(e.begin(), e.end());
    long front = 0;
    for (std::size_t i = beads; i-- > 0;)
      if (emax > 0 && e[i] > c.front_fraction * emax) { front = long(i) + 1; break; }
    const double energy = chain.total_energy(st, t), part = participation(e);
    rec.series.data.insert(rec.series.data.end(),
                           {t, energy, double(front), part, boundary.left.motion(t)});
    S.max_energy = std::max(S.max_energy, energy);
    S.max_participation = std::max(S.max_participation, part);
    S.final_energy = energy;
    S.final_participation = part;
    final_peaks = double(count_peaks(e, 0.1));
    if (t >= next_st - 1e-9 * c.t_end) {
      field.times.push_back(t);
      for (double v : e) field.values.push_back(float(v));
      next_st += c.spacetime_every;
    }
    for (double ts : snap_times) {
      if (std::abs(ts - t) > 1e-9 * c.t_end) continue;
      rec.snapshots.push_back(displacement_snapshot(L, st, e, t, fmt::format("t{:.1f}", t), 1));
      break;
    }
    if (control.on_sample)
      control.on_sample({t, 1, {L.primary(st), beads}, {L.secondary(st), beads}, 1, {e.data(), beads}});
    if (control.progress) control.progress(t / c.t_end);
    return true;
  };
  // At step boundaries: periodic and final checkpoints; on an interrupt, a checkpoint and stop.
  auto at_boundary = [&](const State& st, double t, double next_step, const IntegrationStats& work) {
    const bool stop = control.stop_requested() && t < times.back();  // at the end: just finish
    if (stop || sink.due(t))
      sink.write(st, t, next_step, work, rec,
                 {{"max_energy", S.max_energy}, {"max_participation", S.max_participation},
                  {"final_energy", S.final_energy}, {"final_participation", S.final_participation},
                  {"final_peaks", final_peaks}, {"next_spacetime_row", next_st}});
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
  S.blow_up = locate_blow_up(S.stats, beads, 1);
  S.final_peaks = long(final_peaks);
  // The front speed: least-squares slope of the series' front column over the fit window.
  std::vector<double> front_t, front_n;
  for (Index r = 0; r < rec.series.rows(); ++r) {
    const double t = rec.series.at(r, 0);
    if (t >= c.front_fit_start - 1e-9 && t <= c.front_fit_end + 1e-9) {
      front_t.push_back(t);
      front_n.push_back(rec.series.at(r, 2));
    }
  }
  S.front_speed = least_squares_slope(front_t, front_n);
  S.front_samples = long(front_t.size());
  return result;
}

}  // namespace lrchain::sim
