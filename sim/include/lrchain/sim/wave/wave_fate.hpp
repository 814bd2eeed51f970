#pragma once
// What an exact travelling wave becomes (docs/waves.md, "The fate of a wave"): the wave U(theta n -
// omega t) on a ring of N sites (theta = 2 pi j / N), plus noise of a given size on every field's
// displacements, integrated well past the growth of its instability (srkn11b, symplectic), and
// classified by three measured quantities sampled once per carrier period:
//   deviation      the departure from the exact wave: max_n |u_0[n](t) - U_0(theta n - omega t)| / A, and for a
//                  translation-invariant model that of the strains, max_n |du_0[n] - dU_0[n]| / (2 A |sin(theta/2)|)
//                  with du[n] = u[n+1] - u[n] (a uniform or long-wave displacement, the mean flow a modulated
//                  wave drives, costs no energy there and leaves the wave itself unchanged);
//   participation  P = (sum_n e_n)^2 / (N sum_n e_n^2) of the energy density |e_n|: 1 for a uniform
//                  wave, about w/N for energy held in w sites;
//   entropy        S = -sum_j p_j log p_j / log N of the spatial spectrum p_j = |u^_0(j)|^2 / sum
//                  of the first field: log 2 / log N for one plane wave, near 1 when every mode is
//                  excited alike.
//   dark           the number of dark structures of e_n (dark_structures.hpp): localized dips of its
//                  envelope in an intact background.
// The fate (over the last tenth of the run): stable when the deviation never exceeded
// kBrokenDeviation and the wave has no growing perturbation (intact when it has one but did not break
// up within the run: run longer); otherwise localized when P < kLocalizedParticipation (bright) or the
// median dark count is at least 1 (dark; both when both), disordered when S > kDisorderedEntropy, and
// else modulated (energy spread over the ring in a few modes).
// Stages (structure_stage): the dark structures' and the bright localization's (P < kLocalizedParticipation,
// counted by peaks) first and last time in a sliding window of kStagePeriods samples that holds them in
// most of its samples: a transient dark stage that the last tenth no longer shows.
// Thresholds: site energies of a thermalised ring are exponentially distributed (Gibbs), which gives
// P = E[e]^2 / E[e^2] = 1/2, and a wave under a sinusoidal envelope P = 2/3; energy held in fewer
// sites than half the thermal value, P < 1/4, is localized.
// Frequencies: over the last kFrequencyPeriods carrier periods the first field's velocity is sampled
// kSamplesPerPeriod times a period at every site; the frequency at the deepest dark structure (at its
// half-depth edge: the centre of a black one does not move) and at the highest energy peak is
// zero_crossing_frequency of that site's velocity, to be set against the branch's linear band.
#include <atomic>
#include <cmath>
#include <cstdint>
#include <string_view>
#include <vector>

#include "lrchain/index.hpp"
#include "lrchain/compiled_model_abi.h"
#include "lrchain/sim/wave/dark_structures.hpp"
#include "lrchain/sim/wave/travelling_wave.hpp"

namespace lrchain::sim::wave {

inline constexpr double kBrokenDeviation = 0.1;          // the wave broke up: a tenth of A
inline constexpr double kLocalizedParticipation = 0.25;  // half the thermal value 1/2
inline constexpr double kMaxEnergyDrift = 1e-6;          // relative energy drift above which the run is refused
inline constexpr double kDisorderedEntropy = 0.5;        // spectrum spread over a power N^0.5 of modes
inline constexpr Index kFrequencyPeriods = 8;            // carrier periods at the end the frequencies come from
inline constexpr Index kSamplesPerPeriod = 8;            // velocity samples per carrier period there
inline constexpr Index kStagePeriods = 100;              // samples (carrier periods) of a stage's sliding window

enum class WaveFate { stable, intact, modulated, localized, disordered };
std::string_view to_string(WaveFate f);
enum class LocalizedKind { none, bright, dark, both };  // what a localized fate holds
std::string_view to_string(LocalizedKind k);

// A stage of localized structures in a series of counts (one sample a carrier period): a window of
// `window` consecutive samples holds them when more than half of its samples count at least one; the
// stage runs from the first sample with a structure in the first such window to the last in the last one
// (gaps between held windows included). NaN times and count 0 when no window holds them.
struct StructureStage {
  double from = NAN, until = NAN;  // times of its first and last sample with a structure
  Index count = 0;                 // the largest median count of a held window
  double width = NAN, depth = NAN; // dark: medians of the deepest structure's width and depth over the stage's samples holding one
  bool found() const { return std::isfinite(from); }
};

// The stage of `count` at times `t` with windows of min(window, samples) samples (above); width and depth
// are left NaN.
StructureStage structure_stage(const std::vector<double>& t, const std::vector<double>& count, Index window);

struct WaveFateOptions {
  Index ring_sites = 256;          // N, with theta = 2 pi j / N for an integer j
  double noise = 1e-4;             // standard deviation of the noise, relative to A
  double modulation = 0;           // b: the wave times 1 + b cos(2 pi n / N) (the paper's eq:cimi)
  std::uint64_t seed = 1;          // of the noise (std::mt19937_64)
  double periods = 2000;           // carrier periods 2 pi / omega integrated
  Index steps_per_period = 40;     // srkn11b steps per carrier period
  double growth_rate = 0;          // the wave's largest Floquet-Bloch rate (0: stable), for the fate `intact`
};

struct WaveFateResult {
  std::vector<double> t, deviation, participation, entropy;  // one sample per carrier period, t = 0 first
  std::vector<double> energy_density;  // e_n at the end (N entries)
  double broke_at = -1;                // first t with deviation > kBrokenDeviation (-1: never)
  double participation_end = 0, entropy_end = 0;  // means over the last tenth of the samples
  std::vector<double> dark;            // dark structures counted at each sample
  std::vector<double> dark_width, dark_depth;  // the deepest one's width and depth at each sample (NaN: none)
  std::vector<double> bright;          // bright structures at each sample: peaks of e_n (at least 1) when P < kLocalizedParticipation, else 0
  StructureStage dark_stage, bright_stage;  // the stages of the two series (structure_stage, kStagePeriods)
  bool strain_deviation = false;       // the deviation compares strains (a translation-invariant model)
  Index bright_structures = 0;         // peaks of e_n at the end above 4 x its mean, 3 sites apart
  Index dark_structures = 0;           // the median dark count over the last tenth of the samples
  double dark_seen_fraction = 0;       // share of the samples after the breakup with a dark structure
  Index envelope_window = 3;           // sites of the dark envelope's running mean
  std::vector<DarkStructure> dark_end; // the dark structures at the end, deepest first
  double dark_background_spread = 0;   // (q3 - q1) / b of the envelope's background at the end
  double dark_frequency = NAN;         // at the deepest dark structure's half-depth edge at the end (NaN: none, or < 3 crossings)
  Index dark_site = -1;                // that edge's site (-1: none)
  double bright_frequency = NAN;       // at the highest energy peak at the end, when bright_structures > 0
  Index bright_site = -1;              // that peak's site (-1: none)
  LocalizedKind kind = LocalizedKind::none;
  double max_relative_energy_drift = 0;
  WaveFate fate = WaveFate::stable;
  bool interrupted = false;
};

// omega = pi (crossings - 1) / (t_last - t_first) from the zero crossings of x_k - mean (x_k = x[k stride]
// at t = k dt, linearly interpolated); NaN with fewer than 3 crossings.
double zero_crossing_frequency(const double* x, Index count, Index stride, double dt);

// The run above for `wave` (solved at `theta` = 2 pi j / options.ring_sites on `kernels` with
// `parameters`). InvalidParameter("ring_sites") when theta is not on the ring; NumericalFailure when
// the run blows up (a non-finite state). `stop` (e.g. SIGINT) ends it early with `interrupted`.
WaveFateResult wave_fate(const lrchain_lattice_kernels& kernels, const std::vector<double>& parameters,
                         const TravellingWave& wave, const WaveFateOptions& options,
                         const std::atomic<bool>* stop = nullptr);

}  // namespace lrchain::sim::wave
