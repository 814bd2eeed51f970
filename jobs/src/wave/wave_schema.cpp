// The travelling wave job's option schema (wave_job.hpp): the help `lrchain wave ... --help` shows.
#include "lrchain/jobs/wave_job.hpp"

namespace lrchain::jobs::wave {

namespace {

std::vector<JobOption> make_options() {
  const WaveConfig d;
  const nlohmann::json none;
  const std::vector<std::string> one{"solve", "stability", "fate", "standing"},
      all{"solve", "continue", "stability", "fate", "standing"}, stable{"stability", "fate"}, fate{"fate"},
      ring{"fate", "standing"};
  return {
      {"branch", "--branch", "branch", all, none, false,
       "the model's branch names (`lrchain derive` lists them: acoustic/optical or branch0, ...)",
       "dispersion branch of the wave", "", "the model's only branch (required when it has several)"},
      {"theta", "--theta", "theta", all, none, true, "in (-pi, pi], any real value there",
       "carrier wavenumber theta of u_n(t) = U(theta n - omega t), e.g. 2.5 or 3*pi/4"},
      {"amplitude", "--amplitude", "amplitude", one, none, true, "(0, 1000]",
       "A: the first field's cos(xi) harmonic (the NLS's U)"},
      {"ramp", "--ramp", "ramp", one, d.ramp, false, "[1, 1000]",
       "continuation steps from the linear wave: amplitudes A/ramp, 2A/ramp, ..., A"},
      {"amplitudes", "--amplitudes", "amplitudes", {"continue"}, none, false, "increasing, in (0, 1000]",
       "the amplitudes A of the branch omega(A), each seeded by the previous wave", "", "none (required)"},
      {"initial_harmonics", "--harmonics", "harmonics", all, d.initial_harmonics, false, "[2, 256]",
       "harmonics H of the first collocation (2H+1 phases)"},
      {"max_harmonics", "--max-harmonics", "max_harmonics", all, d.max_harmonics, false, "[harmonics, 256]",
       "H doubles up to this while the tail is above --tail-tolerance"},
      {"tail_tolerance", "--tail-tolerance", "tail_tolerance", all, d.tail_tolerance, false, "(0, 1)",
       "largest harmonic k > 2H/3 of any field, relative to A, that counts as resolved"},
      {"tolerance", "--tolerance", "tolerance", all, d.tolerance, false, "(0, 1)",
       "Newton converged when max |omega^2 U'' - a| <= this x omega_linear^2 A"},
      {"max_iterations", "--max-iterations", "max_iterations", all, d.max_iterations, false, "[1, 1000]",
       "Newton iterations per amplitude"},
      {"k_points", "--k-points", "k_points", stable, d.k_points, false, "[1, 100000]",
       "perturbation wavenumbers K_i = pi (i/k_points)^2, i = 1..k_points (dense near K = 0)"},
      {"unstable_tolerance", "--unstable-tolerance", "unstable_tolerance", stable, d.unstable_tolerance, false,
       "(0, 1)", "Re lambda above this x omega counts as growth"},
      {"ring_sites", "--ring-sites", "ring_sites", ring, d.ring_sites, false, "[8, 100000]",
       "sites N of the ring the perturbed wave runs on (fate) or the standing wave's Floquet multipliers are "
       "computed on (standing); theta moves to the nearest 2 pi j / N"},
      {"noise", "--noise", "noise", fate, d.noise, false, "[0, 1)",
       "standard deviation of the noise added to every displacement, relative to A"},
      {"modulation", "--modulation", "modulation", fate, d.modulation, false, "[0, 1)",
       "the wave's displacements and velocities on the ring times 1 + this x cos(2 pi n / N) (the paper's modulation b of "
       "experiment 7)"},
      {"seed", "--seed", "seed", fate, d.seed, false, "[1, 2147483647]", "seed of the noise"},
      {"periods", "--periods", "periods", fate, d.periods, false, "0 (auto) or [1, 1e6]",
       "carrier periods 2 pi/omega integrated; 0: three times the predicted breakup ln(0.1/noise)/rate (noise 0: "
       "1e-16), in [2000, 1e5]"},
      {"steps_per_period", "--steps-per-period", "steps_per_period", fate, d.steps_per_period, false, "[8, 10000]",
       "srkn11b steps per carrier period"},
      {"format", "--format", "", all, d.format, false, "csv|hdf5",
       "data files in --out: csv (CSV and figures) or hdf5 (also result.h5: the waves, the profile, the growth "
       "rates, the summary; lrchain.load reads it)"},
  };
}

}  // namespace

const std::vector<JobOption>& wave_options() { return schema_once<make_options>(); }

}  // namespace lrchain::jobs::wave
