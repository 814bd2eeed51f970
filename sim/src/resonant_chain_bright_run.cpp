// Bright-breather experiment (Sec. 4.1-4.3): lattice from eq:focus_app/eq:focus_ini vs the ansatz.
#include "lrchain/sim/resonant_chain_bright_run.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <initializer_list>
#include <fmt/format.h>

#include "lrchain/ansatz/bright_breather.hpp"
#include "lrchain/checked_number.hpp"
#include "lrchain/errors.hpp"
#include "lrchain/sim/automatic_step.hpp"
#include "lrchain/sim/displacement_lattice.hpp"
#include "lrchain/sim/integrator.hpp"
#include "lrchain/sim/energy.hpp"
#include "lrchain/sim/least_squares.hpp"
#include "observation.hpp"
#include "lrchain/sim/strain_sites.hpp"
#include "checkpointing.hpp"
#include "sampling_checks.hpp"

namespace lrchain::sim {

namespace {


// Sample intervals floor(periods / sample_every) of the run (validated: no overflow).
Index sample_intervals(const BrightRunConfig& c) { return sim::sample_intervals(c.periods, c.sample_every, "periods"); }

}  // namespace

std::vector<double> snapshot_periods_in_run(const BrightRunConfig& c) {
  return times_inside_run(c.snapshot_periods, default_bright_snapshot_periods(), c.periods);
}

namespace {

// The sizes the run's memory and output grow with.
LatticeRunSizes run_sizes(const BrightRunConfig& c) {
  return sampled_run_sizes(2 * double(c.N) + 2, c.periods, c.sample_every, c.spacetime_every,
                           double(snapshot_periods_in_run(c).size()), c.integrator.stepper, "periods");
}

}  // namespace

ResourceEstimate estimate_resources(const BrightRunConfig& c) { return estimate_lattice_run(run_sizes(c)); }

void validate(const BrightRunConfig& c) {
  validate(c.params);
  check_half_width(c.N, bright_sites);
  if (!(c.periods > 0 && std::isfinite(c.periods)))
    throw InvalidParameter("periods", "must be a finite number > 0 (units of T_b)");
  validate_sampling({c.periods, "periods", true, c.sample_every, c.spacetime_every, c.checkpoint_every,
                     snapshot_periods_in_run(c),
                     (c.checkpoint_at_end && !c.checkpoint_file.empty()) || !c.restart_file.empty(),
                     "snapshot_periods", {}, [&c](double periods) {
                       BrightRunConfig longer = c;
                       longer.periods = periods;
                       return run_sizes(longer);
                     }, c.max_memory});
  if (!(c.theta > 0 && c.theta <= M_PI)) throw InvalidParameter("theta", "the carrier wavenumber must be in (0, pi]");
  if (!(std::isfinite(c.n0) && std::abs(c.n0) <= double(c.N)))
    throw InvalidParameter("n0", fmt::format("the initial centre must be a site of the lattice, in [-N, N] = [{}, {}] "
                                             "(sites = 2N + 1 = {})", -c.N, c.N, strain_site_count(c.N)));
  if (c.detuning) checked_finite(*c.detuning, "detuning");
  checked_finite(c.error_window_end, "error_window_end");
  if (c.centre_window < 1) throw InvalidParameter("centre_window", "must be >= 1");
  validate(c.integrator);
  // The ansatz checks theta, detuning and n0 and gives T_b: dt may not exceed the run periods * T_b.
  const BrightBreatherAnsatz ansatz(c.params, c.branch, c.theta, c.detuning, c.n0);
  const double run_length = c.periods * ansatz.period();
  validate_step_within_run(c.integrator, run_length);
  if (!(c.error_window_end <= run_length))
    throw InvalidParameter("error_window_end", fmt::format("the end of the error window (error_window_end) must be at "
                                                       "most {:.6g}, the run's time span (<= 0: none)", run_length));
  if (!(c.trailing.fit_start >= 0 && c.trailing.fit_start <= run_length))
    throw InvalidParameter("trailing_fit_start", fmt::format("must be in [0, {:.6g}], the run's time span (0: off)",
                                                             run_length));
  const LatticeRunSizes sizes = run_sizes(c);  // also checks the sample counts
  const bool lattice = lattice_dominates(sizes);
  check_memory(estimate_lattice_run(sizes), c.max_memory, lattice ? "sites" : "periods",
               lattice ? "lower sites" : "lower periods or raise sample-every and spacetime-every");
}


namespace {

// The integrator the run uses: with an automatic step (no dt given), srkn11b's step comes from a
// probe of the energy error over the first 2 T_b; a chain with prescribed (ansatz) ends is not
// autonomous, so there the default falls back to the adaptive rkf78.
IntegratorOptions resolved_integrator(const BrightRunConfig& c, const DisplacementLattice& chain,
                                      const State& initial, double Tb, std::optional<StepChoice>& choice) {
  IntegratorOptions o = c.integrator;
  if (!o.automatic_dt || !is_symplectic(o.stepper)) return o;
  o.automatic_dt = false;
  if (!chain.autonomous()) {
    o.stepper = StepperKind::rkf78;
    return o;
  }
  choice = choose_symplectic_step(chain, initial, c.sample_every * Tb, o.stepper, {c.step_energy_error_target, 2 * Tb});
  o.dt = choice->dt;
  return o;
}

}  // namespace

namespace {

// The workspace's lattice for this run: kept when the parameters, the bead count and the ends are
// those of the previous run (prescribed ends follow workspace.ansatz), else built anew.
const DisplacementLattice& workspace_lattice(const BrightRunConfig& c, BrightWorkspace& w, std::size_t beads, Index N) {
  const Params& p = c.params;
  const Params& q = w.chain_params;
  if (w.chain && w.chain_beads == Index(beads) && w.chain_ansatz_ends == c.ansatz_ends && p.alpha == q.alpha &&
      p.delta0 == q.delta0 && p.kappa == q.kappa && p.rho == q.rho)
    return *w.chain;
  const Index first = -N - 1;
  DisplacementBoundary boundary;
  if (c.ansatz_ends) {
    boundary.left.kind = boundary.right.kind = EndKind::prescribed;
    boundary.left.motion = [&w, first](double t) {
      double u, v;
      w.ansatz->displacements(double(first - 1), t, u, v);
      return u;
    };
    boundary.right.motion = [&w, N](double t) {
      double u, v;
      w.ansatz->displacements(double(N + 1), t, u, v);
      return u;
    };
  }
  w.chain.reset();
  w.chain.emplace(c.params, beads, boundary);
  w.chain_params = c.params;
  w.chain_beads = Index(beads);
  w.chain_ansatz_ends = c.ansatz_ends;
  return *w.chain;
}

// Empties the record, keeping the capacity of its series and space-time rows.
void clear_record(RunRecord& rec) {
  rec.series.data.clear();
  rec.fields.resize(1);
  rec.fields[0].times.clear();
  rec.fields[0].values.clear();
  rec.snapshots.clear();
}

}  // namespace

BrightRunResult run_resonant_chain_bright(const BrightRunConfig& c, const RunControl& control) {
  BrightWorkspace workspace;
  BrightRunResult result;
  result.summary = run_resonant_chain_bright(c, workspace, control);
  result.record = std::move(workspace.record);
  return result;
}

BrightRunSummary run_resonant_chain_bright(const BrightRunConfig& c, BrightWorkspace& w, const RunControl& control) {
  validate(c);
  require_checkpoint_store(control, c.checkpoint_file, c.restart_file);
  const BrightBreatherAnsatz ansatz(c.params, c.branch, c.theta, c.detuning, c.n0);
  const Index N = c.N;
  const std::size_t beads = std::size_t(2 * N + 2);  // labels -N-1 .. N
  const Index first = -N - 1;
  const std::size_t strains = beads - 1;             // labels -N .. N

  w.ansatz = &ansatz;
  const DisplacementLattice& chain = workspace_lattice(c, w, beads, N);
  const auto& L = chain.layout();

  State& s = w.state;
  s.assign(L.size(), 0.0);
  for (std::size_t i = 0; i < beads; ++i) {
    const double n = double(first + long(i));
    ansatz.displacements(n, 0.0, L.primary(s)[i], L.secondary(s)[i]);
    ansatz.velocities(n, 0.0, L.primary_rate(s)[i], L.secondary_rate(s)[i]);
  }

  BrightRunSummary S;
  S.omega = ansatz.omega();
  S.omega_b = ansatz.omega_b();
  S.period = ansatz.period();
  S.group_velocity = ansatz.group_velocity();
  S.curvature = ansatz.nls().curvature;
  S.h_tilde = ansatz.nls().h_tilde;
  S.M1 = ansatz.M1();
  S.M2 = ansatz.M2();
  S.inverse_width = ansatz.inverse_width();

  // Observation times: regular samples, plus the snapshot times.
  const double Tb = ansatz.period(), t_end = c.periods * Tb, h = c.sample_every * Tb;
  const Index samples = sample_intervals(c);
  std::vector<double>& times = w.times;
  times.clear();
  times.reserve(static_cast<std::size_t>(samples) + 2);
  for (Index k = 0; k <= samples; ++k) times.push_back(double(k) * h);
  if (t_end - times.back() > 1e-9 * t_end) times.push_back(t_end);
  std::vector<double>& snap_times = w.snapshot_times;
  snap_times.clear();
  for (double p : snapshot_periods_in_run(c))  // later ones belong to a continuation
    if (p <= c.periods * (1 + 1e-12)) snap_times.push_back(std::min(p * Tb, t_end));
  times = merge_observation_times(std::move(times), snap_times, t_end);
  const double st_every = c.spacetime_every * Tb;

  auto& rec = w.record;
  clear_record(rec);
  rec.series.names = {"t", "E_x", "E_y", "energy", "X"};
  rec.fields[0].quantity = "energy_density";
  rec.fields[0].first_label = first;
  rec.fields[0].sites = beads;

  S.integrator = resolved_integrator(c, chain, s, Tb, S.step_choice);

  // What defines the trajectory and its record; a restart must match every item.
  TrajectoryIdentity identity = base_identity("bright", c.params, S.integrator);
  identity.add("branch", c.branch == Branch::optical ? "optical" : "acoustic");
  identity.add("theta", c.theta);
  identity.add("detuning", c.detuning ? fmt::format("{}", *c.detuning) : std::string("default"));
  identity.add("n0", c.n0);
  identity.add("N", N, {"sites", [](long half_width) { return long(strain_site_count(half_width)); }});
  identity.add("ansatz_ends", c.ansatz_ends ? "true" : "false");
  identity.add("sample_every", c.sample_every);
  identity.add("spacetime_every", c.spacetime_every);
  identity.add("centre_window", long(c.centre_window));
  identity.add("error_window_end", c.error_window_end);
  identity.add_state_hash("initial_state", s);

  std::vector<double>&x = w.x, &y = w.y, &xa = w.x_ansatz, &ya = w.y_ansatz, &e = w.energy_density, &scratch = w.scratch;
  for (std::vector<double>* v : {&x, &y, &xa, &ya}) v->assign(strains, 0.0);
  e.assign(beads, 0.0);
  scratch.assign(beads + 1, 0.0);
  double next_st = 0;
  bool first_sample = true, skip_first = false;
  double resume_step = 0;
  CheckpointSink sink;
  sink.store = &control.checkpoints;
  sink.identity = &identity;
  sink.t_end = t_end;
  sink.at_end = c.checkpoint_at_end;
  if (control.checkpoints.load) {
    const Resumption r = resume_from_checkpoint(
        control.checkpoints, identity, "bright", beads, t_end, s, rec,
        {{"x0_inf", &S.x0_inf}, {"y0_inf", &S.y0_inf}, {"energy0", &S.energy0}, {"max_Ex", &S.max_Ex},
         {"max_Ey", &S.max_Ey}, {"max_Ex_window", &S.max_Ex_window}, {"max_Ey_window", &S.max_Ey_window},
         {"final_Ex", &S.final_Ex}, {"final_Ey", &S.final_Ey}, {"max_energy_drift", &S.max_energy_drift},
         {"next_spacetime_row", &next_st}},
        sink, times);
    first_sample = false;
    skip_first = true;  // the checkpoint's record already holds the observation at its time
    resume_step = r.next_step;
    S.t_start = r.t;
  }
  sink.rhythm = CheckpointRhythm(c.checkpoint_every * Tb, S.t_start);
  SpaceTime& row_field = rec.fields[0];  // (after a restart, the checkpoint's)

  auto observe = [&](const State& st, double t) {
    if (skip_first) {
      skip_first = false;
      return true;
    }
    const double* u = L.primary(st);
    const double* v = L.secondary(st);
    for (std::size_t i = 0; i < strains; ++i) {
      x[i] = u[i + 1] - u[i];
      y[i] = v[i + 1] - v[i];
    }
    ansatz.strains(-N, t, xa, ya);
    double ex = 0, ey = 0;
    if (first_sample) {
      for (std::size_t i = 0; i < strains; ++i) {
        S.x0_inf = std::max(S.x0_inf, std::abs(x[i]));
        S.y0_inf = std::max(S.y0_inf, std::abs(y[i]));
      }
    }
    for (std::size_t i = 0; i < strains; ++i) {
      ex = std::max(ex, std::abs(x[i] - xa[i]));
      ey = std::max(ey, std::abs(y[i] - ya[i]));
    }
    ex /= S.x0_inf;
    ey /= S.y0_inf;
    const double energy = chain.total_energy(st, t);
    energy_density(chain, st, t, e, scratch);
    const double X = energy_centre(e, c.centre_window) + double(first);
    if (first_sample) S.energy0 = energy;
    first_sample = false;
    S.max_Ex = std::max(S.max_Ex, ex);
    S.max_Ey = std::max(S.max_Ey, ey);
    if (c.error_window_end > 0 && t <= c.error_window_end) {
      S.max_Ex_window = std::max(S.max_Ex_window, ex);
      S.max_Ey_window = std::max(S.max_Ey_window, ey);
    }
    S.final_Ex = ex;
    S.final_Ey = ey;
    if (chain.autonomous())
      S.max_energy_drift = std::max(S.max_energy_drift, std::abs(energy - S.energy0) / S.energy0);
    rec.series.data.insert(rec.series.data.end(), {t, ex, ey, energy, X});
    if (t >= next_st - 1e-9 * t_end) {
      row_field.times.push_back(t);
      for (double val : e) row_field.values.push_back(float(val));
      next_st += st_every;
    }
    for (double ts : snap_times) {
      if (std::abs(ts - t) > 1e-9 * t_end) continue;
      Snapshot snap;
      snap.t = t;
      snap.tag = fmt::format("t{:.0f}", t);
      snap.names = {"n", "x", "y", "x_ansatz", "y_ansatz", "e"};
      for (std::size_t i = 0; i < strains; ++i)
        snap.data.insert(snap.data.end(),
                         {double(-N + long(i)), x[i], y[i], xa[i], ya[i], e[i + 1]});
      rec.snapshots.push_back(std::move(snap));
      break;
    }
    if (control.on_sample)
      control.on_sample({t, -N, {x.data(), strains}, {y.data(), strains}, first, {e.data(), beads}});
    if (control.progress) control.progress(t / t_end);
    return true;
  };
  // At step boundaries: periodic and final checkpoints; on an interrupt, a checkpoint and stop.
  auto at_boundary = [&](const State& st, double t, double next_step, const IntegrationStats& work) {
    const bool stop = control.stop_requested() && t < times.back();  // at the end: just finish
    if (stop || sink.due(t))
      sink.write(st, t, next_step, work, rec,
                 {{"x0_inf", S.x0_inf}, {"y0_inf", S.y0_inf}, {"energy0", S.energy0},
                  {"max_Ex", S.max_Ex}, {"max_Ey", S.max_Ey}, {"max_Ex_window", S.max_Ex_window},
                  {"max_Ey_window", S.max_Ey_window}, {"final_Ex", S.final_Ex},
                  {"final_Ey", S.final_Ey}, {"max_energy_drift", S.max_energy_drift},
                  {"next_spacetime_row", next_st}});
    return !stop;
  };

  const auto start = std::chrono::steady_clock::now();
  S.stats = integrate_observed(chain, s, times, observe, S.integrator, at_boundary, resume_step, control.stop);
  S.solve_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() +
                    (S.step_choice ? S.step_choice->probe_seconds : 0.0);  // the probe is integration too
  S.stats.steps += static_cast<Index>(sink.base_steps);
  S.stats.rhs_evaluations += static_cast<Index>(sink.base_rhs_evaluations);
  S.checkpoints_written = sink.written;
  S.last_checkpoint_time = sink.last_time;
  S.t_end = S.stats.t_reached;
  S.interrupted = S.stats.stopped;
  S.blew_up = S.stats.blew_up;
  S.blow_up = locate_blow_up(S.stats, beads, first);
  // The energy centre X(t) (eq:ectr) is the series' last column.
  std::vector<double>&centre_t = w.centre_t, &centre_x = w.centre_x;
  centre_t.clear();
  centre_x.clear();
  for (Index r = 0; r < rec.series.rows(); ++r) {
    centre_t.push_back(rec.series.at(r, 0));
    centre_x.push_back(rec.series.at(r, 4));
  }
  S.centre_speed = least_squares_slope(centre_t, centre_x);
  if (!centre_x.empty()) {
    S.centre_start = centre_x.front();
    S.centre_end = centre_x.back();
  }
  // x, y hold the strains of the last observation.
  S.trailing = track_trailing_structure(rec.fields[0], centre_t, centre_x, x, y, -N, c.trailing);
  w.ansatz = nullptr;
  return S;
}

}  // namespace lrchain::sim
