// Automatic step of the symplectic steppers from a probe run's energy error (automatic_step.hpp).
#include "lrchain/sim/automatic_step.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>

#include "lrchain/checked_number.hpp"
#include "lrchain/dispersion.hpp"
#include "lrchain/errors.hpp"

namespace lrchain::sim {
namespace {

constexpr double stability_fraction = 0.9;  // dt * omega_max at most this (well inside stability)
constexpr Index max_probe_runs = 4;

// Largest linear frequency of the resonant chain: the optical branch over theta in [0, pi].
double largest_linear_frequency(const Params& p) {
  double w = 0;
  constexpr int points = 256;
  for (int i = 0; i <= points; ++i)
    w = std::max(w, dispersion_omega(p, Branch::optical, M_PI * double(i) / points));
  return w;
}

// Max relative energy error over [0, probe_time] with `steps` equal steps per sample interval.
double probe_energy_error(const DisplacementLattice& chain, const State& initial, double sample_interval,
                          Index steps, double probe_time, StepperKind stepper) {
  std::vector<double> times;
  const auto samples = std::max<Index>(1, Index(std::ceil(probe_time / sample_interval - 1e-9)));
  for (Index k = 0; k <= samples; ++k) times.push_back(double(k) * sample_interval);
  IntegratorOptions o;
  o.stepper = stepper;
  o.dt = sample_interval / double(steps);
  State s = initial;
  const double energy0 = chain.total_energy(s, 0.0);
  double worst = 0;
  const auto stats = integrate_observed(chain, s, times, [&](const State& st, double t) {
    worst = std::max(worst, std::abs(chain.total_energy(st, t) - energy0) / std::abs(energy0));
    return true;
  }, o);
  if (stats.blew_up || !std::isfinite(worst)) return HUGE_VAL;
  return worst;
}

}  // namespace

int symplectic_order(StepperKind k) {
  switch (k) {
    case StepperKind::symplectic: return 4;
    case StepperKind::srkn11b:
    case StepperKind::srkn14a: return 6;
    case StepperKind::ss17: return 8;
    default: throw InvalidParameter("stepper", "an automatic step needs a symplectic stepper");
  }
}

StepChoice choose_symplectic_step(const DisplacementLattice& chain, const State& initial,
                                  double sample_interval, StepperKind stepper,
                                  const AutomaticStepOptions& options) {
  const auto start = std::chrono::steady_clock::now();
  const int order = symplectic_order(stepper);
  StepChoice c;
  c.largest_linear_frequency = largest_linear_frequency(chain.params());
  const double longest = stability_fraction / c.largest_linear_frequency;
  constexpr Index most_steps = detail::max_fixed_steps;
  const std::string what = "steps per sample interval of the automatic step";
  Index steps = checked_count(sample_interval / longest, "dt", 1, most_steps, what);
  for (c.probe_runs = 1;; ++c.probe_runs) {
    c.probe_energy_error = probe_energy_error(chain, initial, sample_interval, steps, options.probe_time, stepper);
    if (c.probe_energy_error <= options.energy_error_target || c.probe_runs == max_probe_runs) break;
    // error ~ dt^order: the step that meets the target, at least one more step per sample.
    const double shrink = std::isfinite(c.probe_energy_error)
                              ? std::pow(options.energy_error_target / c.probe_energy_error, 1.0 / order)
                              : 0.5;
    steps = std::max(steps + 1, checked_count(double(steps) / shrink, "dt", 1, most_steps, what));
  }
  if (c.probe_energy_error > options.energy_error_target)
    throw NumericalFailure("no step found for " + std::string(to_string(stepper)) +
                           " that keeps the energy error below the target (" +
                           std::to_string(c.probe_energy_error) + " after " +
                           std::to_string(c.probe_runs) + " probes): give --dt or use rkf78");
  c.probe_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  c.steps_per_sample = steps;
  c.dt = sample_interval / double(steps);
  return c;
}

}  // namespace lrchain::sim
