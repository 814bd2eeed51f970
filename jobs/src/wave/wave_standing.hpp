#pragma once
// The standing wave step of the wave job (`lrchain wave standing`, docs/waves.md "Standing waves"): its
// checks, its run, its JSON and its files, called by validate/run/to_json/write (wave_job.hpp).
#include <array>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "lrchain/jobs/output_files.hpp"
#include "lrchain/jobs/wave_job.hpp"

namespace lrchain::jobs::wave {

// The solver options (travelling or standing) from the job's: harmonics, tail, Newton tolerance and steps.
template <class Options>
Options solver_options(const WaveConfig& c) {
  Options o;
  o.initial_harmonics = c.initial_harmonics;
  o.max_harmonics = c.max_harmonics;
  o.tail_tolerance = c.tail_tolerance;
  o.newton_tolerance = c.tolerance;
  o.max_newton_steps = c.max_iterations;
  return o;
}

// The ramp A/ramp, 2A/ramp, ..., A of solve, stability, fate and standing.
std::vector<double> ramp_amplitudes(const WaveConfig& c);

// InvalidParameter("theta") unless the ring's theta is inside (0, pi) and the first field moves in its mode;
// InvalidParameter("model") when the model has no reflection symmetry (no standing wave).
void check_standing(const WaveConfig& c);

// The ramp of standing waves on one spatial period of the ring (theta = 2 pi p / q: q sites), then the
// last wave's Floquet multipliers on the ring of c.ring_sites sites; no wave is reported in r.failure.
void run_standing(const WaveConfig& c, WaveResult& r);

// {ring_sites, period_sites, ring_theta, reflection, waves, omega, coefficients, floquet}.
nlohmann::json standing_json(const WaveResult& r);

// The wave's positions u_f[n] (fields x sites, field-major) at t = 0 and at a quarter period t = pi / (2 omega):
// standing_profile.csv's and result.h5's profiles.
std::array<Eigen::VectorXd, 2> standing_profiles(const sim::wave::StandingWave& w);

// standing.csv (the ramp), standing_profile.csv (u_f[n] at t = 0 and t = T/4 over one spatial period),
// floquet.csv and floquet.gp (the multipliers in the complex plane with the unit circle).
void write_standing(const WaveResult& r, const std::string& dir, Figures& figures);

}  // namespace lrchain::jobs::wave
