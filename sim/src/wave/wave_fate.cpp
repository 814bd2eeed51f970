// The fate of a travelling wave on a ring (wave_fate.hpp).
#include "lrchain/sim/wave/wave_fate.hpp"

#include <algorithm>
#include <cmath>
#include <complex>
#include <numbers>
#include <random>

#include <fmt/format.h>
#include <unsupported/Eigen/FFT>

#include "lrchain/errors.hpp"
#include "lrchain/sim/integrator.hpp"
#include "lrchain/sim/model_lattice.hpp"

namespace lrchain::sim::wave {

std::string_view to_string(WaveFate f) {
  switch (f) {
    case WaveFate::stable: return "stable";
    case WaveFate::intact: return "intact";
    case WaveFate::modulated: return "modulated";
    case WaveFate::localized: return "localized";
    case WaveFate::disordered: return "disordered";
  }
  return "";
}

std::string_view to_string(LocalizedKind k) {
  switch (k) {
    case LocalizedKind::none: return "none";
    case LocalizedKind::bright: return "bright";
    case LocalizedKind::dark: return "dark";
    case LocalizedKind::both: return "both";
  }
  return "";
}

namespace {

// The spatial power spectrum of a ring's displacements by FFT (Eigen's FFT, plan and buffers made
// once, so nothing allocates per observation).
class SpatialSpectrum {
 public:
  explicit SpatialSpectrum(Index n) : samples_(std::size_t(n)), modes_(std::size_t(n / 2 + 1)) {
    fft_.SetFlag(Eigen::FFT<double>::HalfSpectrum);
  }
  // S = -sum_j p_j log p_j / log N over the N modes (+j and -j counted apart), p_j the share of |x_j|^2.
  double entropy(const double* x) {
    const Index n = Index(samples_.size());
    std::copy(x, x + n, samples_.begin());
    fft_.fwd(modes_, samples_);
    double total = 0, sum_plogp = 0;
    for (Index j = 0; j <= n / 2; ++j) total += weight(j, n) * std::norm(modes_[std::size_t(j)]);
    if (!(total > 0)) return 0;
    for (Index j = 0; j <= n / 2; ++j) {
      const double p = std::norm(modes_[std::size_t(j)]) / total;  // each of the weight(j) modes
      if (p > 0) sum_plogp += weight(j, n) * p * std::log(p);
    }
    return -sum_plogp / std::log(double(n));
  }

 private:
  static double weight(Index j, Index n) { return (j == 0 || 2 * j == n) ? 1.0 : 2.0; }  // modes +j and -j
  Eigen::FFT<double> fft_;
  std::vector<double> samples_;
  std::vector<std::complex<double>> modes_;
};

double participation(const std::vector<double>& e) {
  double s = 0, s2 = 0;
  for (double x : e) s += std::abs(x), s2 += x * x;
  return s2 > 0 ? s * s / (double(e.size()) * s2) : 1.0;
}

// Peaks of e above 4 x its mean, merged when closer than 3 sites (periodic).
Index count_peaks(const std::vector<double>& e) {
  const Index n = Index(e.size());
  double mean = 0;
  for (double x : e) mean += std::abs(x);
  mean /= double(n);
  Index count = 0, last = -1000, first = -1;
  for (Index i = 0; i < n; ++i) {
    const double x = std::abs(e[std::size_t(i)]);
    const bool peak = x > 4 * mean && x >= std::abs(e[std::size_t((i + n - 1) % n)]) &&
                      x >= std::abs(e[std::size_t((i + 1) % n)]);
    if (!peak) continue;
    if (i - last >= 3) ++count;
    if (first < 0) first = i;
    last = i;
  }
  if (count > 1 && first + n - last < 3) --count;  // the first and last peaks wrap around
  return count;
}

}  // namespace

// omega = pi (crossings - 1) / (t_last - t_first) over the zero crossings of x - mean (wave_fate.hpp).
double zero_crossing_frequency(const double* x, Index count, Index stride, double dt) {
  double mean = 0;
  for (Index k = 0; k < count; ++k) mean += x[k * stride] / double(count);
  double first = 0, last = 0;
  Index crossings = 0;
  for (Index k = 0; k + 1 < count; ++k) {
    const double a = x[k * stride] - mean, b = x[(k + 1) * stride] - mean;
    if (!((a < 0 && b >= 0) || (a >= 0 && b < 0))) continue;
    const double t = (double(k) + a / (a - b)) * dt;
    if (crossings++ == 0) first = t;
    last = t;
  }
  return crossings >= 3 ? std::numbers::pi * double(crossings - 1) / (last - first) : NAN;
}


WaveFateResult wave_fate(const lrchain_lattice_kernels& kernels, const std::vector<double>& parameters,
                         const TravellingWave& wave, const WaveFateOptions& o, const std::atomic<bool>* stop) {
  const Index n = o.ring_sites, fields = kernels.fields;
  const double modes = wave.theta * double(n) / (2 * std::numbers::pi);
  if (std::abs(modes - std::round(modes)) > 1e-9 * double(n))
    throw InvalidParameter("ring_sites", fmt::format("theta = {} is not 2 pi j / {} for an integer j", wave.theta, n));
  const CompiledLattice ring(kernels, parameters, n, true, LatticeForm::displacement);
  State s(std::size_t(2 * fields * n));
  std::vector<std::vector<std::complex<double>>> harmonics;
  for (Index f = 0; f < fields; ++f) harmonics.push_back(wave_harmonics(wave, f));
  std::mt19937_64 random(o.seed);
  std::normal_distribution<double> noise(0.0, o.noise > 0 ? o.noise * wave.amplitude : 1.0);  // (used when noise > 0)
  for (Index f = 0; f < fields; ++f)
    for (Index i = 0; i < n; ++i) {
      double u, du;
      profile_at(harmonics[std::size_t(f)], wave.theta * double(i), u, du);
      const double envelope = 1 + o.modulation * std::cos(2 * std::numbers::pi * double(i) / double(n));
      s[std::size_t(f * n + i)] = envelope * u + (o.noise > 0 ? noise(random) : 0.0);
      s[std::size_t(fields * n + f * n + i)] = -envelope * wave.omega * du;  // d/dt U(theta n - omega t)
    }
  const double period = 2 * std::numbers::pi / wave.omega;
  // One sample a period; over the last kFrequencyPeriods, kSamplesPerPeriod velocity samples a period.
  const Index periods = Index(std::ceil(o.periods)), tail_periods = std::min(kFrequencyPeriods, periods);
  const Index tail_start = periods - tail_periods, tail_samples = tail_periods * kSamplesPerPeriod + 1;
  std::vector<double> times;
  std::vector<char> whole_period;
  for (Index p = 0; p <= periods; ++p)
    for (Index k = 0; k < (p >= tail_start && p < periods ? kSamplesPerPeriod : 1); ++k) {
      times.push_back((double(p) + double(k) / double(kSamplesPerPeriod)) * period);
      whole_period.push_back(k == 0);
    }
  IntegratorOptions opt;
  opt.stepper = StepperKind::srkn11b;
  opt.dt = period / double(o.steps_per_period);

  WaveFateResult r;
  for (auto* series : {&r.t, &r.deviation, &r.participation, &r.entropy, &r.dark, &r.dark_width, &r.dark_depth, &r.bright})
    series->reserve(std::size_t(periods + 1));
  std::vector<double> e(static_cast<std::size_t>(n)), exact(static_cast<std::size_t>(n));
  // A translation-invariant model's energy depends on differences only: its departure is that of the
  // strains, relative to the fundamental's strain amplitude 2 A |sin(theta / 2)| (theta != 0 on the ring).
  r.strain_deviation = wave.translation_invariant && std::abs(std::sin(wave.theta / 2)) > 1e-12;
  const double scale = wave.amplitude * (r.strain_deviation ? 2 * std::abs(std::sin(wave.theta / 2)) : 1.0);
  SpatialSpectrum spectrum(n);
  r.envelope_window = envelope_window(wave.theta);
  DarkStructureScan dark(n, r.envelope_window);
  std::vector<double> velocity(std::size_t(tail_samples * n));  // [sample][site] of the first field
  Index observation = 0, tail_row = 0;
  const double e0 = ring.energy(s);
  const auto observe = [&](const State& x, double t) {
    const bool whole = whole_period[std::size_t(observation++)];
    if (t >= (double(tail_start) - 0.25 / double(kSamplesPerPeriod)) * period && tail_row < tail_samples)
      std::copy(x.begin() + fields * n, x.begin() + fields * n + n, velocity.begin() + tail_row++ * n);
    if (!whole) return true;
    double deviation = 0;
    for (Index i = 0; i < n; ++i) {
      double u, du;
      profile_at(harmonics[0], wave.theta * double(i) - wave.omega * t, u, du);
      exact[std::size_t(i)] = u;
    }
    for (Index i = 0; i < n; ++i) {  // the displacement's departure, or (translation-invariant) the strain's
      const std::size_t j = std::size_t((i + 1) % n);
      const double d = r.strain_deviation ? (x[j] - x[std::size_t(i)]) - (exact[j] - exact[std::size_t(i)])
                                          : x[std::size_t(i)] - exact[std::size_t(i)];
      deviation = std::max(deviation, std::abs(d) / scale);
    }
    ring.energy_density(x.data(), x.data() + ring.positions(), e.data());
    r.t.push_back(t);
    r.deviation.push_back(deviation);
    const double p = participation(e);
    r.participation.push_back(p);
    r.entropy.push_back(spectrum.entropy(x.data()));
    const Index count = dark.scan(e.data());
    r.dark.push_back(double(count));
    r.dark_width.push_back(count > 0 ? dark.structures().front().width : NAN);
    r.dark_depth.push_back(count > 0 ? dark.structures().front().depth : NAN);
    r.bright.push_back(p < kLocalizedParticipation ? double(std::max<Index>(1, count_peaks(e))) : 0.0);
    if (r.broke_at < 0 && deviation > kBrokenDeviation) r.broke_at = t;
    r.max_relative_energy_drift = std::max(r.max_relative_energy_drift, std::abs(ring.energy(x) - e0) / std::abs(e0));
    return true;
  };
  const IntegrationStats stats = integrate_observed(ring, s, times, observe, opt, {}, 0, stop);
  if (stats.blew_up) throw NumericalFailure(fmt::format("the ring run blew up after t = {:.6g}", stats.t_reached));
  if (r.t.empty()) throw NumericalFailure("the ring run made no observation");
  // The classification rides on thresholds of P and S: a run whose energy drifted is not trusted.
  if (!(r.max_relative_energy_drift <= kMaxEnergyDrift))
    throw NumericalFailure(fmt::format("the ring run's relative energy drift {:.3g} exceeds {:.0e}: the fate is not "
                                       "trusted; raise steps_per_period (now {})",
                                       r.max_relative_energy_drift, kMaxEnergyDrift, o.steps_per_period));
  r.interrupted = stats.stopped;
  r.energy_density = e;
  const std::size_t samples = r.t.size(), tail = std::max<std::size_t>(1, samples / 10);
  for (std::size_t i = samples - tail; i < samples; ++i) {
    r.participation_end += r.participation[i] / double(tail);
    r.entropy_end += r.entropy[i] / double(tail);
  }
  std::vector<double> tail_counts(r.dark.end() - std::ptrdiff_t(tail), r.dark.end());
  std::nth_element(tail_counts.begin(), tail_counts.begin() + std::ptrdiff_t(tail / 2), tail_counts.end());
  r.dark_structures = Index(tail_counts[tail / 2]);
  Index after = 0, seen = 0;
  for (std::size_t i = 0; i < samples; ++i)
    if (r.broke_at >= 0 && r.t[i] >= r.broke_at) ++after, seen += r.dark[i] > 0;
  r.dark_seen_fraction = after > 0 ? double(seen) / double(after) : 0.0;
  r.bright_stage = structure_stage(r.t, r.bright, kStagePeriods);
  r.dark_stage = structure_stage(r.t, r.dark, kStagePeriods);
  if (r.dark_stage.found()) {  // the deepest structure's width and depth over the stage's samples holding one
    std::vector<double> widths, depths;
    for (std::size_t i = 0; i < samples; ++i)
      if (r.t[i] >= r.dark_stage.from && r.t[i] <= r.dark_stage.until && r.dark[i] > 0)
        widths.push_back(r.dark_width[i]), depths.push_back(r.dark_depth[i]);
    const auto median = [](std::vector<double>& v) {
      std::nth_element(v.begin(), v.begin() + std::ptrdiff_t(v.size() / 2), v.end());
      return v[v.size() / 2];
    };
    r.dark_stage.width = median(widths);
    r.dark_stage.depth = median(depths);
  }
  dark.scan(e.data());  // the end state's structures (the last sample's scan)
  r.dark_end = dark.structures();
  r.dark_background_spread = dark.background_spread();
  r.bright_structures = count_peaks(e);
  const bool tail_complete = tail_row == tail_samples;
  const double dt = period / double(kSamplesPerPeriod);
  if (tail_complete && !r.dark_end.empty()) {  // at its half-depth edge: a black soliton's centre is at rest
    r.dark_site = Index(std::lround(r.dark_end.front().right)) % n;
    if (r.dark_site < 0) r.dark_site += n;
    r.dark_frequency = zero_crossing_frequency(velocity.data() + r.dark_site, tail_samples, n, dt);
  }
  if (r.bright_structures > 0) {
    r.bright_site = Index(std::max_element(e.begin(), e.end(), [](double a, double b) { return std::abs(a) < std::abs(b); }) -
                          e.begin());
    if (tail_complete) r.bright_frequency = zero_crossing_frequency(velocity.data() + r.bright_site, tail_samples, n, dt);
  }
  const bool bright = r.participation_end < kLocalizedParticipation, dark_found = r.dark_structures > 0;
  if (r.broke_at < 0) r.fate = o.growth_rate > 0 ? WaveFate::intact : WaveFate::stable;
  else if (bright || dark_found) {
    r.fate = WaveFate::localized;
    r.kind = bright && dark_found ? LocalizedKind::both : bright ? LocalizedKind::bright : LocalizedKind::dark;
  } else if (r.entropy_end > kDisorderedEntropy) r.fate = WaveFate::disordered;
  else r.fate = WaveFate::modulated;
  return r;
}

}  // namespace lrchain::sim::wave
