// evolve_bright_breather: period-by-period integration of a bright breather, its deviation, energy
// and growth rate (bright_evolution.hpp).
#include "lrchain/sim/bright/bright_evolution.hpp"

#include <cmath>
#include <numbers>

namespace lrchain::sim::bright {

namespace {

// Least-squares slope of ln y against t over samples[0..last].
double log_slope(const std::vector<BrightEvolutionSample>& samples, Index last) {
  double st = 0, sy = 0, stt = 0, sty = 0;
  const double n = double(last + 1);
  for (Index m = 0; m <= last; ++m) {
    const double t = samples[std::size_t(m)].t, y = std::log(samples[std::size_t(m)].deviation);
    st += t, sy += y, stt += t * t, sty += t * y;
  }
  return (n * sty - st * sy) / (n * stt - st * st);
}

}  // namespace

BrightEvolution evolve_bright_breather(const dark::DarkShooting& shooting, const Eigen::VectorXd& z0, double omega_b,
                                       Index periods, const Eigen::VectorXd& perturbation, double saturation) {
  const Index P = z0.size();
  const CompiledLattice& lattice = shooting.orbit().lattice();
  BrightEvolution e;
  e.period = 2 * std::numbers::pi / omega_b;
  e.has_energy = lattice.has_energy();
  std::vector<double> state(std::size_t(2 * P), 0.0);
  for (Index i = 0; i < P; ++i) state[std::size_t(i)] = z0(i);
  if (perturbation.size() == 2 * P)
    for (Index i = 0; i < 2 * P; ++i) state[std::size_t(i)] += perturbation(i);
  const double peak = z0.cwiseAbs().maxCoeff();
  // deviation from [Z(0), 0] and energy of the current state at time t
  const auto sample = [&](double t) {
    double deviation = 0;
    for (Index i = 0; i < 2 * P; ++i)
      deviation = std::max(deviation, std::abs(state[std::size_t(i)] - (i < P ? z0(i) : 0.0)));
    return BrightEvolutionSample{t, deviation, e.has_energy ? lattice.energy(state) : 0.0};
  };
  e.samples.reserve(std::size_t(periods + 1));
  e.samples.push_back(sample(0));
  const double energy0 = e.samples[0].energy;
  const dark::OrbitAdvance advance = shooting.advance();
  for (Index m = 1; m <= periods; ++m) {
    advance(state, double(m - 1) * e.period, double(m) * e.period);
    e.samples.push_back(sample(double(m) * e.period));
    e.profile_drift = std::max(e.profile_drift, e.samples.back().deviation / peak);
    if (e.has_energy && energy0 != 0)
      e.energy_drift = std::max(e.energy_drift, std::abs(e.samples.back().energy - energy0) / std::abs(energy0));
  }
  Index last = -1;  // the last period before saturation, all deviations positive
  while (last + 1 <= periods && e.samples[std::size_t(last + 1)].deviation < saturation * peak &&
         e.samples[std::size_t(last + 1)].deviation > 0)
    ++last;
  if (last >= 2) {
    e.fit_last = last;
    e.growth_rate = log_slope(e.samples, last);
  }
  return e;
}

}  // namespace lrchain::sim::bright
