#include "lrchain/sim/dark/measures.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "lrchain/checked_number.hpp"

namespace lrchain::sim::dark {

namespace {
std::vector<double> initial_state(const Eigen::VectorXd& z0) {
  std::vector<double> s(static_cast<std::size_t>(2 * z0.size()), 0.0);
  for (Eigen::Index i = 0; i < z0.size(); ++i) s[static_cast<std::size_t>(i)] = z0(i);
  return s;
}
double relative_error(const std::vector<double>& s, const Eigen::VectorXd& z0) {
  double e = 0, zm = 0;
  for (Eigen::Index i = 0; i < z0.size(); ++i) {
    e = std::max(e, std::abs(s[static_cast<std::size_t>(i)] - z0(i)));
    zm = std::max(zm, std::abs(z0(i)));
  }
  return e / zm;
}
}  // namespace

DarkMeasures measure_dark_orbit(const OrbitAdvance& advance, const Eigen::VectorXd& z0, Index sites, double omega_b,
                                Index samples) {
  const Index N = sites;
  const Index fields = z0.size() / N;
  std::vector<double> s = initial_state(z0);
  const double period = 2.0 * std::numbers::pi / omega_b;
  std::vector<double> lo(static_cast<std::size_t>(fields)), hi(static_cast<std::size_t>(fields));
  for (Index f = 0; f < fields; ++f) lo[std::size_t(f)] = hi[std::size_t(f)] = s[static_cast<std::size_t>(f * N)];
  double strain_max = z0.head(N).maxCoeff();
  for (Index k = 1; k <= samples; ++k) {
    advance(s, period * (k - 1) / samples, period * k / samples);
    for (Index f = 0; f < fields; ++f) {
      lo[std::size_t(f)] = std::min(lo[std::size_t(f)], s[static_cast<std::size_t>(f * N)]);
      hi[std::size_t(f)] = std::max(hi[std::size_t(f)], s[static_cast<std::size_t>(f * N)]);
    }
    for (Index n = 0; n < N; ++n) strain_max = std::max(strain_max, s[static_cast<std::size_t>(n)]);
  }
  DarkMeasures m;
  m.E_b = relative_error(s, z0);
  std::vector<double> centre(static_cast<std::size_t>(fields)), amplitude(static_cast<std::size_t>(fields));
  for (Index f = 0; f < fields; ++f) {
    centre[std::size_t(f)] = 0.5 * (hi[std::size_t(f)] + lo[std::size_t(f)]);     // eq:center
    amplitude[std::size_t(f)] = 0.5 * (hi[std::size_t(f)] - lo[std::size_t(f)]);  // eq:amp
  }
  m.C_x = centre[0];
  m.K_x = amplitude[0];
  if (fields > 1) {
    m.C_y = centre[1];
    m.K_y = amplitude[1];
  }
  m.max_strain = strain_max;
  double norm = 0;  // eq:l2norm
  for (Index n = 0; n < N; ++n)
    for (Index f = 0; f < fields; ++f)
      norm += amplitude[std::size_t(f)] * amplitude[std::size_t(f)] - (z0(f * N + n) - centre[std::size_t(f)]) * (z0(f * N + n) - centre[std::size_t(f)]);
  m.norm_squared = norm;
  return m;
}

DarkMeasures measure_dark_breather(const Params& p, const Eigen::VectorXd& z0, double omega_b,
                                   const ContactIntegrationOptions& integration, Index samples) {
  const Index N = z0.size() / 2;
  StrainLatticeOrbit orbit(p, N);
  ContactIntegrator integrator(orbit, integration);
  return measure_dark_orbit([&](std::vector<double>& s, double t0, double t1) { integrator.integrate(s, t0, t1); },
                            z0, N, omega_b, samples);
}

std::vector<RelativeErrorSample> relative_error_history(const Params& p, const Eigen::VectorXd& z0,
                                                        double omega_b, double t_end,
                                                        const ContactIntegrationOptions& integration) {
  const Index N = z0.size() / 2;
  StrainLatticeOrbit orbit(p, N);
  ContactIntegrator integrator(orbit, integration);
  std::vector<double> s = initial_state(z0);
  const double period = 2.0 * std::numbers::pi / omega_b;
  const Index periods = checked_count(std::floor(t_end / period), "t_end", 0, std::numeric_limits<int>::max(),
                                      "periods (t-end / T_b)");
  std::vector<RelativeErrorSample> out;
  out.reserve(static_cast<std::size_t>(periods));
  for (Index m = 1; m <= periods; ++m) {
    integrator.integrate(s, (m - 1) * period, m * period);
    out.push_back({m * period, relative_error(s, z0)});
  }
  return out;
}

std::vector<Eigen::VectorXd> dark_breather_evolution(const Params& p, const Eigen::VectorXd& z0,
                                                     double dt, Index steps,
                                                     const ContactIntegrationOptions& integration) {
  const Index N = z0.size() / 2;
  StrainLatticeOrbit orbit(p, N);
  ContactIntegrator integrator(orbit, integration);
  std::vector<double> s = initial_state(z0);
  std::vector<Eigen::VectorXd> out;
  out.push_back(z0);
  for (Index k = 1; k <= steps; ++k) {
    integrator.integrate(s, (k - 1) * dt, k * dt);
    out.push_back(Eigen::Map<const Eigen::VectorXd>(s.data(), 2 * N));
  }
  return out;
}

}  // namespace lrchain::sim::dark
