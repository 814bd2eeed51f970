// The travelling wave job's run (wave_job.hpp): the linear wave at theta, continuation in A, stability.
#include <chrono>

#include "lrchain/jobs/wave_job.hpp"

namespace lrchain::jobs::wave {

WaveResult run(const WaveConfig& c) {
  validate(c);
  const auto start = std::chrono::steady_clock::now();
  WaveResult r;
  r.config = c;
  const Index branch = c.model->branch_or_only(c.branch);
  r.branch = c.model->definition().branch_names[std::size_t(branch)];
  r.nls = coefficients_from_evaluators(*c.model, branch, c.theta);
  r.mode = sim::bloch_mode(*c.model, *c.kernels, branch, c.theta);
  sim::wave::WaveLattice lattice(*c.kernels, sim::lattice_parameters(*c.model), c.theta);
  sim::wave::TravellingWaveOptions options;
  options.initial_harmonics = c.initial_harmonics;
  options.max_harmonics = c.max_harmonics;
  options.tail_tolerance = c.tail_tolerance;
  options.newton_tolerance = c.tolerance;
  options.max_newton_steps = c.max_iterations;
  std::vector<double> amplitudes = c.amplitudes;
  if (c.step != WaveStep::branch) {
    amplitudes.clear();
    for (Index i = 1; i <= c.ramp; ++i) amplitudes.push_back(c.amplitude * double(i) / double(c.ramp));
  }
  sim::wave::WaveBranch found = sim::wave::continue_travelling_wave(lattice, r.mode, amplitudes, options);
  r.waves = std::move(found.waves);
  r.failure = found.stopped;
  r.failed_at = found.stopped_at;
  if (c.step == WaveStep::stability && !r.failure) {
    sim::wave::WaveStabilityOptions so;
    so.k_points = c.k_points;
    so.unstable_tolerance = c.unstable_tolerance;
    r.stability = sim::wave::wave_stability(lattice, r.waves.back(), so);
  }
  r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return r;
}

}  // namespace lrchain::jobs::wave
