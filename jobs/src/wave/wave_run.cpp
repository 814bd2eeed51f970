// The travelling wave job's run (wave_job.hpp): the linear wave at theta, continuation in A, stability.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <numbers>

#include "lrchain/errors.hpp"

#include "lrchain/jobs/wave_job.hpp"
#include "wave_standing.hpp"

namespace lrchain::jobs::wave {

double auto_periods(double omega, double growth_rate, double noise) {
  const double period = 2 * std::numbers::pi / omega;
  if (!(growth_rate > 0)) return 2000;
  const double breakup = std::log(sim::wave::kBrokenDeviation / std::max(noise, kRoundOff)) / growth_rate;
  return std::clamp(std::ceil(3 * breakup / period), 2000.0, 1e5);
}

double ring_theta(double theta, Index sites) {
  return 2 * std::numbers::pi * std::round(theta * double(sites) / (2 * std::numbers::pi)) / double(sites);
}

WaveResult run(const WaveConfig& c) {
  validate(c);
  const auto start = std::chrono::steady_clock::now();
  WaveResult r;
  r.config = c;
  const Index branch = c.model->branch_or_only(c.branch);
  r.branch = c.model->definition().branch_names[std::size_t(branch)];
  r.theta = c.step == WaveStep::fate || c.step == WaveStep::standing ? ring_theta(c.theta, c.ring_sites) : c.theta;
  r.nls = coefficients_from_evaluators(*c.model, branch, r.theta);
  r.mode = sim::bloch_mode(*c.model, *c.kernels, branch, r.theta);
  if (c.step == WaveStep::standing) {
    run_standing(c, r);
    r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return r;
  }
  sim::wave::WaveLattice lattice(*c.kernels, sim::lattice_parameters(*c.model), r.theta);
  const auto options = solver_options<sim::wave::TravellingWaveOptions>(c);
  const std::vector<double> amplitudes = c.step == WaveStep::branch ? c.amplitudes : ramp_amplitudes(c);
  sim::wave::WaveBranch found = sim::wave::continue_travelling_wave(lattice, r.mode, amplitudes, options);
  r.waves = std::move(found.waves);
  r.failure = found.stopped;
  r.failed_at = found.stopped_at;
  if ((c.step == WaveStep::stability || c.step == WaveStep::fate) && !r.failure) {
    sim::wave::WaveStabilityOptions so;
    so.k_points = c.k_points;
    so.unstable_tolerance = c.unstable_tolerance;
    r.stability = sim::wave::wave_stability(lattice, r.waves.back(), so);
  }
  if (c.step == WaveStep::fate && !r.failure) {
    sim::wave::WaveFateOptions fo;
    fo.ring_sites = c.ring_sites;
    fo.noise = c.noise;
    fo.modulation = c.modulation;
    fo.seed = std::uint64_t(c.seed);
    // Only the K = 2 pi m / N the ring holds can grow there: the prediction and the run length use those.
    r.ring_growth = sim::wave::ring_growth(lattice, r.waves.back(), c.ring_sites, c.unstable_tolerance);
    fo.growth_rate = r.ring_growth.rate;
    fo.periods = c.periods > 0 ? c.periods : auto_periods(r.waves.back().omega, fo.growth_rate, c.noise);
    fo.steps_per_period = c.steps_per_period;
    r.band = sim::branch_band(*c.kernels, sim::lattice_parameters(*c.model), branch);
    try {
      r.fate = sim::wave::wave_fate(*c.kernels, sim::lattice_parameters(*c.model), r.waves.back(), fo, c.stop);
    } catch (const NumericalFailure& e) {
      r.failure = e.what();
      r.failed_at = c.amplitude;
      r.ring_run_failed = true;
    }
  }
  r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return r;
}

}  // namespace lrchain::jobs::wave
