#pragma once
// The periodic travelling wave job (`lrchain wave solve|continue|stability`, lrchain.wave) for any
// model: one WaveConfig -> validate -> run -> WaveResult -> write (CSV, gnuplot, summary.json) and
// to_json. The exact wave u_f[n](t) = U_f(theta n - omega t) by collocation in the phase and
// Gauss-Newton (sim/wave/travelling_wave.hpp), its Floquet-Bloch growth rates over K
// (sim/wave/wave_stability.hpp), both beside the NLS predictions (sim/wave/wave_nls.hpp).
// docs/waves.md.
#include <array>
#include <atomic>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "lrchain/coefficients.hpp"
#include "lrchain/jobs/option_schema.hpp"
#include "lrchain/model.hpp"
#include "lrchain/compiled_model_abi.h"
#include "lrchain/sim/model_lattice_bloch.hpp"
#include "lrchain/sim/wave/standing_wave.hpp"
#include "lrchain/sim/wave/travelling_wave.hpp"
#include "lrchain/sim/wave/wave_fate.hpp"
#include "lrchain/sim/wave/wave_stability.hpp"

namespace lrchain::jobs::wave {

enum class WaveStep {
  solve,      // the wave at `amplitude`, continued from amplitude/ramp in `ramp` steps
  branch,     // the branch omega(A) through `amplitudes` (`lrchain wave continue`)
  stability,  // solve, then the growth rate max Re lambda over K in (0, pi]
  fate,       // stability at the ring's theta, then the perturbed wave on a ring: what it becomes
  standing,   // the standing wave (sum of the counter-propagating waves) at the ring's theta and its Floquet multipliers
};

// Every option of the job with its default and range (wave_options()); validate() names a refused one
// by its key.
struct WaveConfig {
  WaveStep step = WaveStep::solve;
  // The lattice: a loaded model and its generated lattice kernels (owned by the caller, alive during run).
  const Model* model = nullptr;
  const lrchain_lattice_kernels* kernels = nullptr;
  std::string branch;                 // dispersion branch (required)
  double theta = 0;                   // carrier wavenumber in (-pi, pi], any real value there (required)
  double amplitude = 0;               // solve, stability: A, the first field's cos xi amplitude, in (0, 1000] (required)
  Index ramp = 4;                     // solve, stability: amplitudes A/ramp, 2A/ramp, ..., A, in [1, 1000]
  std::vector<double> amplitudes;     // branch: increasing amplitudes in (0, 1000] (required)
  Index initial_harmonics = 8;        // H of the first collocation, in [2, 256]
  Index max_harmonics = 128;          // H doubles up to this while the tail is above tail_tolerance, in [initial, 256]
  double tail_tolerance = 1e-10;      // largest harmonic k > 2H/3 relative to A, in (0, 1)
  double tolerance = 1e-11;           // Newton: max residual relative to omega^2 A, in (0, 1)
  Index max_iterations = 30;          // Newton iterations per amplitude, in [1, 1000]
  Index k_points = 200;               // stability: K_i = pi (i/k_points)^2, i = 1..k_points, in [1, 100000]
  double unstable_tolerance = 1e-9;   // stability: Re lambda > this x omega is growth, in (0, 1)
  Index ring_sites = 256;             // fate, standing: sites N of the ring, theta moved to the nearest 2 pi j / N, in [8, 100000]
  double noise = 1e-4;                // fate: noise on every displacement, relative to A, in [0, 1)
  double modulation = 0;              // fate: the wave on the ring times 1 + modulation cos(2 pi n / N) (eq:cimi's b), in [0, 1)
  Index seed = 1;                     // fate: of the noise, in [1, 2^31)
  double periods = 0;                 // fate: carrier periods integrated, in [1, 1e6]; 0: auto_periods
  Index steps_per_period = 40;        // fate: srkn11b steps per carrier period, in [8, 10000]
  const std::atomic<bool>* stop = nullptr;  // fate: raised (e.g. by SIGINT) ends the ring run early
  std::string format = "csv";         // files in `out`: csv (CSV and figures) or hdf5 (also result.h5)
  std::string out;                    // output directory ("": no files)
};

// Every key of WaveConfig with its default, range and one line of documentation (option_schema.hpp).
const std::vector<JobOption>& wave_options();

// Throws InvalidParameter naming the key, InputError for `out`, before anything is computed.
void validate(const WaveConfig& c);

struct WaveResult {
  WaveConfig config;
  std::string branch;                      // the branch's name
  NlsCoefficients nls;                     // the model's NLS coefficients at theta (its derived evaluators)
  sim::BlochMode mode;                     // the linear wave the solve starts from
  std::vector<sim::wave::TravellingWave> waves;  // solve/stability: the ramp (the last at `amplitude`); branch: the branch
  std::optional<std::string> failure;      // no wave at an amplitude: the reason (the CLI's exit 3)
  std::optional<double> failed_at;         // that amplitude
  bool ring_run_failed = false;            // fate: the wave was found, its ring run failed (failure says why)
  sim::wave::RingGrowth ring_growth;       // fate: the largest rate among the ring's K = 2 pi m / N (the prediction's)
  std::optional<sim::wave::WaveStability> stability;
  double theta = 0;                        // the wave's theta: config.theta, or for fate the ring's nearest
  std::optional<sim::wave::WaveFateResult> fate;
  std::array<double, 2> band{0, 0};        // fate: the branch's linear band [min, max] omega (sim::branch_band)
  // standing: the ramp of standing waves (the last at `amplitude`) on one spatial period of the ring, the
  // reflection the model has, and the last wave's Floquet multipliers on the ring of ring_sites sites.
  std::vector<sim::wave::StandingWave> standing;
  std::optional<sim::wave::ReflectionSymmetry> reflection;
  std::optional<sim::wave::StandingFloquet> standing_floquet;
  double seconds = 0;
};

// The size round-off seeds a noise-free ring run with (the run length's noise when noise = 0).
inline constexpr double kRoundOff = 1e-16;

// The fate's run length when not given: three times the predicted breakup ln(0.1 / noise) / rate (noise 0:
// kRoundOff), in
// carrier periods 2 pi / omega, within [2000, 1e5]; 2000 for a stable wave (rate 0).
double auto_periods(double omega, double growth_rate, double noise);

// The ring's wavenumber nearest theta: 2 pi j / sites, j = round(theta sites / 2 pi).
double ring_theta(double theta, Index sites);

// validate(), then the job. No wave at an amplitude ends the job and is reported (failure), not thrown;
// nor is a ring run (fate) that blows up.
WaveResult run(const WaveConfig& c);

// {model, step, branch, theta, options, nls: {...}, waves: [...], profile (solve, stability),
// stability: {k, growth_rate, nls_growth_rate, bands, largest_rate, at_k, nls_largest_rate, nls_k}, failure,
// seconds, provenance}.
nlohmann::json to_json(const WaveResult& r);

// profile.csv (xi and U_f of the last wave), branch.csv (every wave: A, omega and its NLS value, harmonics,
// tail, residual), growth.csv (stability: K, exact and NLS growth rate) with growth.gp, summary.json, and with
// format "hdf5" result.h5 (wave_hdf5.hpp); returns
// to_json(r) with "figures" and "figures_skipped".
nlohmann::json write(const WaveResult& r, const std::filesystem::path& out);

}  // namespace lrchain::jobs::wave
