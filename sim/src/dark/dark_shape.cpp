// The dark-breather shape check of a converged shooting solution (dark_shape.hpp).
#include "lrchain/sim/dark/dark_shape.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

#include <fmt/format.h>

namespace lrchain::sim::dark {

namespace {

// Ring distance from array index i to the nearest dip centre (theta = pi: one dip in the middle;
// theta = 0: the pair at N/4 + n0 and 3N/4 + n0, as dark_seed places them).
double dip_distance(const DarkAnsatz& a, double n0, Index sites, Index i) {
  const double n = static_cast<double>(sites);
  auto ring = [&](double centre) {
    const double d = std::abs(static_cast<double>(i) - centre);
    return std::min(d, n - d);
  };
  if (a.theta != 0) return ring(0.5 * (n - 1) + n0);
  const double first = 0.25 * n + n0;
  return std::min(ring(first), ring(first + 0.5 * n));
}

}  // namespace

std::string dark_shape_failure(const DarkAnsatz& a, DarkCenter center, Index sites, const Eigen::VectorXd& z,
                               const DarkShapeTolerances& tol) {
  // The plane wave's pattern: the seed with unit amplitude and tanh saturated to +-1 (the NLS plane
  // wave on either side of the dip; zero at a site-centred dip's own site).
  DarkAnsatz unit = a;
  unit.amplitude = 1.0;
  unit.inverse_width = 1e6;
  const Eigen::VectorXd pattern = dark_seed(unit, center, sites);
  const Index fields = z.size() / sites;
  const double n0 = dark_center_n0(center);
  double farthest = 0;
  for (Index i = 0; i < sites; ++i) farthest = std::max(farthest, dip_distance(a, n0, sites, i));
  const double far = farthest - std::max(2.0, 0.1 * static_cast<double>(sites));
  const double strongest = pattern.cwiseAbs().maxCoeff();
  // Far from the dip(s) the plane wave takes two values per field, m_f + B P and m_f - B P (P's sign:
  // the carrier's phase on that sublattice and side of the dip; m_f: the wave's mean shift, from
  // even nonlinearities): B from their difference, every far value within the spread of its own.
  struct FieldFar { double plus = 0, minus = 0, magnitude = 0; Index n_plus = 0, n_minus = 0; };
  std::vector<FieldFar> far_values(static_cast<std::size_t>(fields));
  Index far_sites = 0;
  auto for_far = [&](auto&& visit) {
    for (Index i = 0; i < sites; ++i) {
      if (dip_distance(a, n0, sites, i) < far) continue;
      for (Index f = 0; f < fields; ++f)
        if (std::abs(pattern(f * sites + i)) >= 0.25 * strongest) visit(f, f * sites + i);
    }
  };
  for (Index i = 0; i < sites; ++i) far_sites += dip_distance(a, n0, sites, i) >= far ? 1 : 0;
  for_far([&](Index f, Index at) {
    FieldFar& v = far_values[static_cast<std::size_t>(f)];
    v.magnitude = std::abs(pattern(at));
    if (pattern(at) > 0) v.plus += z(at), ++v.n_plus;
    else v.minus += z(at), ++v.n_minus;
  });
  double background = 0, weight = 0;  // B: the mean of (z_+ - z_-)/(2 |P|) over the fields, weighted by |P|
  for (FieldFar& v : far_values) {
    if (v.n_plus == 0 || v.n_minus == 0) continue;
    v.plus /= static_cast<double>(v.n_plus);
    v.minus /= static_cast<double>(v.n_minus);
    background += (v.plus - v.minus) / 2;
    weight += v.magnitude;
  }
  background = weight > 0 ? std::abs(background) / weight : 0.0;  // (-B: the same breather half a period on)
  double spread = 0;
  for_far([&](Index f, Index at) {
    const FieldFar& v = far_values[static_cast<std::size_t>(f)];
    spread = std::max(spread, std::abs(z(at) - (pattern(at) > 0 ? v.plus : v.minus)) / v.magnitude);
  });
  const std::string dip = a.theta != 0 ? "the dip" : "the dips";
  if (!(background > 0) || !(spread <= tol.background_spread * background))
    return fmt::format("the far field is not the plane wave of the edge: its amplitude varies by {:.0f}% over the {} "
                       "sites farthest from {}", 100 * spread / background, far_sites, dip);
  if (!(background <= tol.amplitude_factor * a.amplitude && background >= a.amplitude / tol.amplitude_factor))
    return fmt::format("the far-field amplitude {:.4g} is not the plane wave's at omega_b (NLS amplitude {:.4g}, "
                       "omega_b - omega = h A^2)", background, a.amplitude);
  // The carrying field: the largest far-field pattern (r or u0 at theta = pi, w1 at theta = 0 with mean flow).
  Index carrier = 0;
  for (Index f = 1; f < fields; ++f)
    if (far_values[static_cast<std::size_t>(f)].magnitude > far_values[static_cast<std::size_t>(carrier)].magnitude) carrier = f;
  // The carrier's envelope |z - m_f| / (B |P|) near every dip centre: its smallest value there.
  const FieldFar& c = far_values[static_cast<std::size_t>(carrier)];
  const double mean_shift = (c.plus + c.minus) / 2;
  double shallowest = 0;
  for (int which = 0; which < (a.theta != 0 ? 1 : 2); ++which) {
    const double centre = (a.theta != 0 ? 0.5 * (static_cast<double>(sites) - 1) : 0.25 * static_cast<double>(sites)) +
                          n0 + which * 0.5 * static_cast<double>(sites);
    double lowest = 1e300;
    for (Index i = 0; i < sites; ++i)
      if (std::abs(static_cast<double>(i) - centre) <= 1.5)
        lowest = std::min(lowest, std::abs(z(carrier * sites + i) - mean_shift) / (background * c.magnitude));
    shallowest = std::max(shallowest, lowest);
  }
  if (!(shallowest <= tol.dip_depth))
    return fmt::format("no dip: the carrier next to the centre is {:.0f}% of the far field's", 100 * shallowest);
  return {};
}

}  // namespace lrchain::sim::dark
