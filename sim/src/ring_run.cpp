// Plane waves and wave packets of any model on a periodic ring (ring_run.hpp): the lattice's own
// check of the derived h and c.
#include "lrchain/sim/ring_run.hpp"

#include <cmath>
#include <csignal>
#include <complex>
#include <numbers>

#include <fmt/format.h>

#include "lrchain/checked_number.hpp"
#include "lrchain/coefficient_check.hpp"
#include "lrchain/errors.hpp"
#include "lrchain/sim/integrator.hpp"
#include "lrchain/config/option_caps.hpp"
#include "lrchain/sim/least_squares.hpp"
#include "lrchain/sim/model_lattice.hpp"

namespace lrchain::sim {

namespace {

constexpr double kTwoPi = 2 * std::numbers::pi;

// k with theta = 2 pi k / sites (to 1e-9), or -1.
long mode_number_on(double theta, long sites) {
  const double k = theta * double(sites) / kTwoPi;
  return std::abs(k - std::round(k)) <= 1e-9 * std::max(1.0, k) ? long(std::round(k)) : -1;
}

// Initial state U Re(K g(n) e^{i n theta}) with velocities of the envelope moving at c:
// d/dt [g(n - c t) K e^{i(n theta - omega t)}] = (-i omega g - c g') K e^{i ...} at t = 0.
template <class Envelope>
State wave_state(const CompiledLattice& ring, const BlochMode& mode, double theta, double c, Envelope envelope) {
  const std::size_t fields = ring.fields(), sites = ring.sites();
  State s(2 * fields * sites, 0.0);
  for (std::size_t n = 0; n < sites; ++n) {
    double g = 0, dg = 0;
    envelope(double(n), g, dg);
    const std::complex<double> carrier = std::polar(1.0, theta * double(n));
    for (std::size_t f = 0; f < fields; ++f) {
      const std::complex<double> z = mode.kernel[f] * carrier;
      s[f * sites + n] = g * z.real();
      s[(fields + f) * sites + n] = ((std::complex<double>(0, -mode.omega) * g - c * dg) * z).real();
    }
  }
  return s;
}

IntegratorOptions fixed_step(double omega, double steps_per_period) {
  IntegratorOptions o;
  o.stepper = StepperKind::srkn11b;
  o.dt = kTwoPi / omega / steps_per_period;
  return o;
}

}  // namespace

Index ring_sites(const RingRunConfig& c) {
  if (c.sites > 0) return c.sites;
  for (long n = 8; n <= 4096; ++n)
    if (mode_number_on(c.theta, n) > 0) return n;
  return 0;
}

void validate(const RingRunConfig& c) {
  if (!(c.theta > 0 && c.theta <= std::numbers::pi)) throw InvalidParameter("theta", "the carrier wavenumber must be in (0, pi]");
  if (c.sites != 0 && (c.sites < config::ring_sites.least || c.sites > config::ring_sites.most))
    throw InvalidParameter("sites", fmt::format("the ring needs {} to {} sites", config::ring_sites.least,
                                                config::ring_sites.most));
  const long sites = ring_sites(c);
  if (sites == 0)
    throw InvalidParameter("theta", fmt::format("{} is not 2 pi k / N for any ring of N <= 4096 sites; give theta as "
                                                "a fraction of pi such as 3*pi/8, or --sites N with theta = 2 pi k / N",
                                                c.theta));
  if (mode_number_on(c.theta, sites) <= 0)
    throw InvalidParameter("theta", fmt::format("{} is not a mode of a ring of {} sites: theta must be 2 pi k / {} "
                                                "(k whole)", c.theta, sites, sites));
  if (c.amplitudes.empty() || c.amplitudes.size() > 64)
    throw InvalidParameter("amplitudes", "give 1 to 64 plane-wave amplitudes");
  for (double a : c.amplitudes)
    if (!(a > 0 && a <= 10))
      throw InvalidParameter("amplitudes", "each amplitude must be in (0, 10]: the check is of small amplitudes");
  if (!(c.periods >= 10 && c.periods <= 1e5)) throw InvalidParameter("periods", "must be in [10, 1e5] carrier periods");
  if (!(c.steps_per_period >= 8 && c.steps_per_period <= 1e4))
    throw InvalidParameter("steps-per-period", "must be in [8, 1e4]");
  if (c.packet_amplitude && !(*c.packet_amplitude > 0 && *c.packet_amplitude <= 10))
    throw InvalidParameter("packet-amplitude", "must be in (0, 10] (default: a tenth of the smallest amplitude)");
  if (!(c.packet_width >= 4 && c.packet_width <= 1000)) throw InvalidParameter("packet-width", "must be in [4, 1000] sites");
}

PlaneWaveMeasurement measure_plane_wave(const lrchain_lattice_kernels& kernels, const std::vector<double>& parameters,
                                        const BlochMode& mode, Index sites, Index mode_number, double amplitude,
                                        double periods, double steps_per_period, const std::atomic<bool>* stop) {
  const double theta = kTwoPi * double(mode_number) / double(sites);
  const bool alternating = 2 * mode_number == sites;  // theta = pi: sum_n u_n (-1)^n is real
  const CompiledLattice ring(kernels, parameters, std::size_t(sites), true, LatticeForm::displacement);
  State s = wave_state(ring, mode, theta, 0.0, [amplitude](double, double& g, double& dg) { g = amplitude; dg = 0; });
  const double period = kTwoPi / mode.omega;
  const std::size_t velocities = ring.fields() * std::size_t(sites);  // first field's velocities start here
  constexpr int samples_per_period = 8;
  std::vector<double> times;
  for (long i = 0; i <= long(periods * samples_per_period); ++i) times.push_back(period * double(i) / samples_per_period);
  std::vector<double> t_series, phase_series;
  t_series.reserve(times.size());
  phase_series.reserve(times.size());
  PlaneWaveMeasurement m;
  double previous = 0, unwrapped = 0;
  const IntegrationStats stats = integrate_observed(ring, s, times, [&](const State& x, double t) {
    // Mode sums of u and of the analytic signal u + i u'/omega, and the first field's energy.
    std::complex<double> z = 0, analytic = 0;
    double energy = 0;
    for (long n = 0; n < sites; ++n) {
      const double u = x[std::size_t(n)], v = x[velocities + std::size_t(n)] / mode.omega;
      const std::complex<double> carrier = std::polar(1.0, -theta * double(n));
      z += u * carrier;
      analytic += std::complex<double>(u, v) * carrier;
      energy += u * u + v * v;
    }
    const double fraction = energy > 0 ? std::norm(analytic) / double(sites) / energy : 0.0;
    m.least_carrier_fraction = std::min(m.least_carrier_fraction, fraction);
    if (fraction < kPlaneWaveCarrierFraction) {
      m.broke_up_at = t;
      return false;  // no longer a plane wave: nothing left to measure
    }
    const double phase = std::arg(alternating ? analytic : z);
    if (!t_series.empty()) unwrapped += std::remainder(phase - previous, kTwoPi);
    previous = phase;
    t_series.push_back(t);
    phase_series.push_back(unwrapped);
    return !(stop && stop->load(std::memory_order_relaxed));  // false: stopped (SIGINT)
  }, fixed_step(mode.omega, steps_per_period), {}, 0, stop);
  if (stats.stopped && !m.broke_up_at) throw Interrupted(SIGINT, "interrupted");
  if (stats.blew_up)
    throw NumericalFailure(fmt::format("{}: the plane wave of amplitude {} blew up on the ring at t = {}",
                                       kernels.model_name, amplitude, stats.t_reached));
  if (t_series.size() >= 2) m.frequency = -least_squares_slope(t_series, phase_series);
  return m;
}

double measure_ring_frequency(const lrchain_lattice_kernels& kernels, const std::vector<double>& parameters,
                              const BlochMode& mode, Index sites, Index mode_number, double amplitude, double periods,
                              double steps_per_period, const std::atomic<bool>* stop) {
  return measure_plane_wave(kernels, parameters, mode, sites, mode_number, amplitude, periods, steps_per_period, stop)
      .frequency;
}

double measure_packet_speed(const lrchain_lattice_kernels& kernels, const std::vector<double>& parameters,
                            const BlochMode& mode, double group_velocity, Index sites, Index mode_number,
                            double amplitude, double width, double duration, double steps_per_period,
                            TimeSeries& track, const std::atomic<bool>* stop) {
  const double theta = kTwoPi * double(mode_number) / double(sites);
  const CompiledLattice ring(kernels, parameters, std::size_t(sites), true, LatticeForm::displacement);
  const double n0 = double(sites) / 2;
  State s = wave_state(ring, mode, theta, group_velocity, [&](double n, double& g, double& dg) {
    const double z = (n - n0) / width;
    g = amplitude * std::exp(-0.5 * z * z);
    dg = -g * z / width;
  });
  const std::size_t fields = ring.fields(), count = std::size_t(sites);
  const double period = kTwoPi / mode.omega, omega2 = mode.omega * mode.omega;
  std::vector<double> times;
  const long samples = std::max(20L, long(duration / period));
  for (long i = 0; i <= samples; ++i) times.push_back(duration * double(i) / double(samples));
  track.names = {"t", "packet_centre"};
  track.data.clear();
  std::vector<double> t_series, centre;
  double previous = 0, unwrapped = 0;
  const IntegrationStats stats = integrate_observed(ring, s, times, [&](const State& x, double t) {
    // Circular centroid of the squared envelope sum_f m_f (u_f'^2 + omega^2 u_f^2).
    std::complex<double> z = 0;
    for (std::size_t n = 0; n < count; ++n) {
      double intensity = 0;
      for (std::size_t f = 0; f < fields; ++f) {
        const double u = x[f * count + n], v = x[(fields + f) * count + n];
        intensity += ring.masses()[f] * (v * v + omega2 * u * u);
      }
      z += intensity * std::polar(1.0, kTwoPi * double(n) / double(sites));
    }
    const double angle = std::arg(z);
    if (!t_series.empty()) unwrapped += std::remainder(angle - previous, kTwoPi);
    previous = angle;
    const double X = n0 + unwrapped * double(sites) / kTwoPi;
    t_series.push_back(t);
    centre.push_back(X);
    track.data.insert(track.data.end(), {t, X});
    return !(stop && stop->load(std::memory_order_relaxed));  // false: stopped (SIGINT)
  }, fixed_step(mode.omega, steps_per_period), {}, 0, stop);
  if (stats.stopped) throw Interrupted(SIGINT, "interrupted");
  if (stats.blew_up)
    throw NumericalFailure(fmt::format("{}: the wave packet blew up at t = {}", kernels.model_name, stats.t_reached));
  return least_squares_slope(t_series, centre);
}

RingRunResult run_ring(const Model& model, const lrchain_lattice_kernels& kernels, const RingRunConfig& c) {
  validate(c);
  RingRunResult r;
  r.model = model.name();
  const NlsCoefficients nls = coefficients_from_evaluators(model, c.branch, c.theta);
  r.omega = nls.omega;
  r.h = nls.h;
  r.group_velocity = nls.group_velocity;
  if (nls.evaluation == CoefficientEvaluation::refused)  // no prediction to compare with: exit 3 with the reason
    throw NumericalFailure(fmt::format("the NLS coefficients of {} at theta = {} are singular: {}", model.name(), c.theta,
                                       singular_reason(nls)));
  if (!std::isfinite(r.h))
    throw InvalidParameter("theta", fmt::format("the NLS coefficient h of {} is singular (a resonance) at theta = {}",
                                                model.name(), c.theta));
  r.mode = bloch_mode(model, kernels, c.branch, c.theta);
  const std::vector<double> parameters = lattice_parameters(model);
  r.sites = ring_sites(c);
  r.mode_number = mode_number_on(c.theta, r.sites);
  // The packet ring: a multiple of the plane-wave ring with >= 40 widths; the packet travels a
  // quarter of it (at most 4000 carrier periods).
  r.packet_width = c.packet_width;
  double smallest = c.amplitudes.front();
  for (double U : c.amplitudes) smallest = std::min(smallest, U);
  r.packet_amplitude = c.packet_amplitude.value_or(smallest / 10);
  const long multiple = std::max(1L, long(std::ceil(40 * c.packet_width / double(r.sites))));
  r.packet_sites = multiple * r.sites;
  const double period = 2 * std::numbers::pi / r.omega;
  r.standing = std::abs(r.group_velocity) <= kZeroGroupVelocity * std::max(1.0, r.omega);
  r.packet_duration = !r.standing ? std::min(0.25 * double(r.packet_sites) / std::abs(r.group_velocity),
                                                                4000 * period)
                                                     : 4000 * period;
  // Progress: the share of lattice steps (sites x steps) done; the packet runs at half the steps per period.
  const double wave_work = double(r.sites) * c.periods * c.steps_per_period;
  const double total_work = double(c.amplitudes.size()) * wave_work +
                            double(r.packet_sites) * r.packet_duration / period * c.steps_per_period / 2;
  double work_done = 0;
  for (double U : c.amplitudes) {
    RingAmplitude a;
    a.amplitude = U;
    const PlaneWaveMeasurement m = measure_plane_wave(kernels, parameters, r.mode, r.sites, r.mode_number, U, c.periods,
                                                      c.steps_per_period, c.stop);
    a.measured_frequency = m.frequency;
    a.least_carrier_fraction = m.least_carrier_fraction;
    a.broke_up_at = m.broke_up_at;
    a.predicted_shift = r.h * U * U / 4;
    a.predicted_frequency = r.omega + a.predicted_shift;
    a.measured_shift = a.measured_frequency - r.omega;
    if (std::abs(r.h) > 1e-12 * std::max(1.0, r.omega) && !a.broke_up_at)
      a.relative_disagreement = std::abs(a.measured_shift - a.predicted_shift) / std::abs(a.predicted_shift);
    a.weakly_nonlinear = std::abs(a.predicted_shift) <= kWeaklyNonlinearShift * r.omega;
    if (!a.weakly_nonlinear)
      r.warnings.push_back(fmt::format("amplitude {:g}: |h| U^2/4 = {:.3g} is {:.3g} omega, outside the weakly nonlinear "
                                       "range (<= {:g} omega): the O(U^4) terms of the frequency are not small",
                                       U, std::abs(a.predicted_shift), std::abs(a.predicted_shift) / r.omega,
                                       kWeaklyNonlinearShift));
    if (a.broke_up_at && !r.failure)
      r.failure = fmt::format("amplitude {:g}: not measurable: the plane wave broke up at t = {:.6g} (the fraction of its "
                              "energy in the carrier mode fell to {:.4f} < {:g}; modulational instability)",
                              U, *a.broke_up_at, a.least_carrier_fraction, kPlaneWaveCarrierFraction);
    r.amplitudes.push_back(a);
    work_done += wave_work;
    if (c.progress) c.progress(work_done / total_work);
  }
  r.packet_speed = measure_packet_speed(kernels, parameters, r.mode, r.standing ? 0.0 : r.group_velocity, r.packet_sites,
                                        multiple * r.mode_number, r.packet_amplitude, r.packet_width,
                                        r.packet_duration, c.steps_per_period / 2, r.record.series, c.stop);
  if (c.progress) c.progress(1.0);
  if (!r.standing)
    r.packet_relative_disagreement = std::abs(r.packet_speed - r.group_velocity) / std::abs(r.group_velocity);
  return r;
}

}  // namespace lrchain::sim
