#include "lrchain/sim/dark/evolution.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <limits>
#include <numbers>

#include "lrchain/checked_number.hpp"
#include "lrchain/errors.hpp"

namespace lrchain::sim::dark {

double dark_dip_position(const Eigen::VectorXd& amplitude) {
  const Eigen::Index N = amplitude.size();
  const double top = amplitude.maxCoeff();
  double c = 0, s = 0;
  for (Eigen::Index i = 0; i < N; ++i) {
    const double w = (top - amplitude(i)) * (top - amplitude(i));
    const double phi = 2.0 * std::numbers::pi * static_cast<double>(i) / static_cast<double>(N);
    c += w * std::cos(phi);
    s += w * std::sin(phi);
  }
  double i_mean = std::atan2(s, c) * static_cast<double>(N) / (2.0 * std::numbers::pi);
  if (i_mean < 0) i_mean += static_cast<double>(N);
  double n = i_mean - 0.5 * static_cast<double>(N - 1);
  if (n > 0.5 * static_cast<double>(N)) n -= static_cast<double>(N);
  if (n <= -0.5 * static_cast<double>(N)) n += static_cast<double>(N);
  return n;
}

// Direct integration of eq:Hertzd0S from (Z(0), 0) with per-period measures (eq:relerr, eq:center).
DarkEvolution evolve_dark_orbit(const OrbitAdvance& advance, const Eigen::VectorXd& z0, Index sites, double omega_b,
                                double t_end, Index samples_per_period, const std::atomic<bool>* stop,
                                const std::function<void(double)>& progress, const Eigen::VectorXd& perturbation) {
  if (!(omega_b > 0)) throw InvalidParameter("omega_b", "must be > 0");
  if (samples_per_period < 4) throw InvalidParameter("samples", "at least 4 samples per period");
  const Index N = sites;
  const double period = 2.0 * std::numbers::pi / omega_b;
  if (!(t_end >= period && std::isfinite(t_end)))
    throw InvalidParameter("t_end", "must be a finite time of at least one period T_b = 2 pi/omega_b");
  const Index M = checked_count(std::floor(t_end / period), "t_end", 1, std::numeric_limits<int>::max(),
                                "periods (t-end / T_b)");
  const Eigen::Index positions = z0.size();
  std::vector<double> s(static_cast<std::size_t>(2 * positions), 0.0);
  for (Eigen::Index i = 0; i < positions; ++i) s[static_cast<std::size_t>(i)] = z0(i);
  if (perturbation.size() == 2 * positions)
    for (Eigen::Index i = 0; i < 2 * positions; ++i) s[static_cast<std::size_t>(i)] += perturbation(i);
  else if (perturbation.size() != 0)
    throw std::invalid_argument("evolve_dark_orbit: the perturbation needs 2 x positions entries");
  const Eigen::VectorXd start = Eigen::Map<const Eigen::VectorXd>(s.data(), positions);
  const double zmax = z0.cwiseAbs().maxCoeff();

  DarkEvolution out;
  out.sites = N;
  out.period = period;
  out.snapshots.reserve(static_cast<std::size_t>(M + 1));
  out.snapshots.push_back(start);
  out.periods.reserve(static_cast<std::size_t>(M));
  out.max_strain = start.head(N).maxCoeff();
  Eigen::VectorXd lo(N), hi(N);
  double previous = 0;
  for (Index m = 1; m <= M; ++m) {
    if (stop && stop->load(std::memory_order_relaxed)) break;
    for (Index n = 0; n < N; ++n) lo(n) = hi(n) = s[static_cast<std::size_t>(n)];
    for (Index k = 1; k <= samples_per_period; ++k) {
      const double t0 = period * (static_cast<double>(m - 1) + static_cast<double>(k - 1) / static_cast<double>(samples_per_period));
      const double t1 = period * (static_cast<double>(m - 1) + static_cast<double>(k) / static_cast<double>(samples_per_period));
      advance(s, t0, t1);
      for (Index n = 0; n < N; ++n) {
        const double x = s[static_cast<std::size_t>(n)];
        lo(n) = std::min(lo(n), x);
        hi(n) = std::max(hi(n), x);
      }
    }
    const Eigen::Map<const Eigen::VectorXd> z(s.data(), positions);
    out.snapshots.emplace_back(z);
    out.max_strain = std::max(out.max_strain, hi.maxCoeff());
    DarkEvolutionPeriod r;
    r.t = static_cast<double>(m) * period;
    r.E_b = (z - z0).cwiseAbs().maxCoeff() / zmax;
    r.C_x = 0.5 * (hi(0) + lo(0));
    r.K_x = 0.5 * (hi(0) - lo(0));
    const Eigen::VectorXd amplitude = 0.5 * (hi - lo);
    r.depth = amplitude.maxCoeff() - amplitude.minCoeff();
    double pos = dark_dip_position(amplitude);
    if (m > 1) {  // unwrap across the periodic ends
      const double ring = static_cast<double>(N);
      while (pos - previous > 0.5 * ring) pos -= ring;
      while (pos - previous < -0.5 * ring) pos += ring;
    }
    previous = pos;
    r.position = pos;
    out.periods.push_back(r);
    if (progress) progress(static_cast<double>(m) / static_cast<double>(M));
  }
  return out;
}

DarkEvolution evolve_dark_breather(const Params& p, const Eigen::VectorXd& z0, double omega_b,
                                   double t_end, Index samples_per_period,
                                   const ContactIntegrationOptions& integration,
                                   const std::atomic<bool>* stop, const std::function<void(double)>& progress,
                                   const Eigen::VectorXd& perturbation) {
  const Index N = z0.size() / 2;
  StrainLatticeOrbit orbit(p, N);
  ContactIntegrator integrator(orbit, integration);
  return evolve_dark_orbit([&](std::vector<double>& s, double t0, double t1) { integrator.integrate(s, t0, t1); },
                           z0, N, omega_b, t_end, samples_per_period, stop, progress, perturbation);
}

}  // namespace lrchain::sim::dark
