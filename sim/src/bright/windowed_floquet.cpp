// Windowed Floquet multipliers of a bright breather, certified by full-lattice residuals
// (windowed_floquet.hpp).
#include "lrchain/sim/bright/windowed_floquet.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <numeric>

#include <Eigen/Eigenvalues>
#include <fmt/format.h>

#include "lrchain/errors.hpp"
#include "lrchain/sim/dark/monodromy_product.hpp"

namespace lrchain::sim::bright {

namespace {

using Complex = std::complex<double>;

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// Distance of sites a and b on a ring of n sites.
Index ring_distance(Index a, Index b, Index n) {
  const Index d = std::abs(a - b) % n;
  return std::min(d, n - d);
}

// Full-ring site of window site i (window of `width` sites centred on `center`).
Index full_site(Index center, Index width, Index i, Index n) { return ((center - width / 2 + i) % n + n) % n; }

// The eigenpairs of the dense monodromy of the window ring of `width` sites about `center`, the
// breather's positions restricted to it (field-major), velocities zero as on the full ring.
struct WindowSpectrum {
  Eigen::VectorXcd values;
  Eigen::MatrixXcd vectors;
};

WindowSpectrum window_spectrum(const WindowLattice& lattice, const Eigen::VectorXd& z0, Index full_sites, Index center,
                               Index width, double omega_b) {
  const Index fields = z0.size() / full_sites;
  Eigen::VectorXd zw(fields * width);
  for (Index f = 0; f < fields; ++f)
    for (Index i = 0; i < width; ++i) zw[f * width + i] = z0[f * full_sites + full_site(center, width, i, full_sites)];
  const dark::DarkShooting window(*lattice.kernels, lattice.parameters, width, lattice.mean_flow,
                                  dark::ShootingMode::reversible, {}, lattice.contacts);
  Eigen::EigenSolver<Eigen::MatrixXd> solver(window.monodromy(zw, omega_b), true);
  if (solver.info() != Eigen::Success) throw NumericalFailure("windowed Floquet: eigenvalue solver failed");
  return {solver.eigenvalues(), solver.eigenvectors()};
}

// ||v on the window's outer `margin` sites (each end)|| / ||v||: small for a mode localized at the core.
double edge_fraction(const Eigen::VectorXcd& v, Index width, Index margin) {
  double edge = 0;
  for (Index k = 0; k < v.size(); ++k) {
    const Index i = k % width;
    if (i < margin || i >= width - margin) edge += std::norm(v[k]);
  }
  return std::sqrt(edge) / v.norm();
}

// The window eigenvector v (blocks of `width` sites: positions then velocities, field-major) on the full ring.
Eigen::VectorXcd embed(const Eigen::VectorXcd& v, Index center, Index width, Index full_sites) {
  const Index blocks = v.size() / width;
  Eigen::VectorXcd full = Eigen::VectorXcd::Zero(blocks * full_sites);
  for (Index b = 0; b < blocks; ++b)
    for (Index i = 0; i < width; ++i) full[b * full_sites + full_site(center, width, i, full_sites)] = v[b * width + i];
  return full;
}

// ||M v - lambda v|| / ||v|| with M v from real products (M real: M v = M Re v + i M Im v).
double residual(const dark::MonodromyProduct& product, const Eigen::VectorXcd& v, Complex lambda) {
  const Eigen::VectorXd re = v.real(), im = v.imag();
  Eigen::VectorXd mre(re.size()), mim = Eigen::VectorXd::Zero(im.size());
  product.apply(re.data(), mre.data());
  if (im.norm() > 0) product.apply(im.data(), mim.data());
  Eigen::VectorXcd mv(v.size());
  mv.real() = mre;
  mv.imag() = mim;
  return (mv - lambda * v).norm() / v.norm();
}

}  // namespace

WindowedFloquet windowed_floquet(const dark::DarkShooting& shooting, const WindowLattice& lattice,
                                 const Eigen::VectorXd& z0, double omega_b, const WindowedFloquetOptions& o) {
  const auto start = std::chrono::steady_clock::now();
  WindowedFloquet r;
  const Index n = shooting.sites(), fields = z0.size() / n;
  r.full_sites = n;
  // The core: the peak site and the farthest site above fraction x peak.
  Eigen::VectorXd amplitude = Eigen::VectorXd::Zero(n);
  for (Index f = 0; f < fields; ++f)
    for (Index s = 0; s < n; ++s) amplitude[s] = std::max(amplitude[s], std::abs(z0[f * n + s]));
  const double peak = amplitude.maxCoeff(&r.center);
  Index half = 0;
  for (Index s = 0; s < n; ++s)
    if (amplitude[s] > o.fraction * peak) half = std::max(half, ring_distance(s, r.center, n));
  r.sites = std::min({n, o.cap, std::max<Index>(9, 2 * (half + o.margin) + 1)});
  r.check_sites = std::min(n, Index(std::ceil(1.5 * double(r.sites))));
  const WindowSpectrum first = window_spectrum(lattice, z0, n, r.center, r.sites, omega_b);
  const WindowSpectrum second = window_spectrum(lattice, z0, n, r.center, r.check_sites, omega_b);
  // Trivial +1 multipliers: the trivial_expected nearest +1.
  const Index values = first.values.size();
  std::vector<Index> order(static_cast<std::size_t>(values));
  std::iota(order.begin(), order.end(), Index(0));
  std::sort(order.begin(), order.end(),
            [&](Index a, Index b) { return std::abs(first.values[a] - 1.0) < std::abs(first.values[b] - 1.0); });
  const Index trivial = std::min<Index>(values, lattice.mean_flow ? 4 : 2);
  std::vector<Index> localized;
  for (Index k = 0; k < values; ++k) {
    const Index i = order[std::size_t(k)];
    if (k < trivial && std::abs(first.values[i] - 1.0) <= o.trivial_tolerance) {
      r.trivial.push_back(first.values[i]);
      continue;
    }
    if (r.sites < n && edge_fraction(first.vectors.col(i), r.sites, o.margin) > o.edge_weight)
      r.max_extended_modulus = std::max(r.max_extended_modulus, std::abs(first.values[i]));
    else
      localized.push_back(i);
  }
  std::stable_sort(localized.begin(), localized.end(),
                   [&](Index a, Index b) { return std::abs(first.values[a]) > std::abs(first.values[b]); });
  r.localized_found = Index(localized.size());
  if (Index(localized.size()) > o.count) localized.resize(std::size_t(o.count));
  r.window_seconds = seconds_since(start);
  // Certification on the full lattice.
  const auto certify_start = std::chrono::steady_clock::now();
  const dark::MonodromyProduct product(shooting, z0, omega_b);
  for (Index i : localized) {
    WindowedMultiplier m;
    m.lambda = first.values[i];
    m.window_difference = (second.values.array() - m.lambda).abs().minCoeff();
    // A conjugate of an earlier multiplier has the conjugate eigenvector: the same residual.
    const auto conjugate = std::find_if(r.localized.begin(), r.localized.end(), [&](const WindowedMultiplier& e) {
      return m.lambda.imag() != 0 && std::abs(e.lambda - std::conj(m.lambda)) <= 1e-12 * std::abs(m.lambda);
    });
    m.residual = conjugate != r.localized.end()
                     ? conjugate->residual
                     : std::optional(residual(product, embed(first.vectors.col(i), r.center, r.sites, n), m.lambda));
    if (*m.residual > o.residual_tolerance)
      m.reason = fmt::format("full-lattice residual {:.2e} > {:.0e}", *m.residual, o.residual_tolerance);
    else if (m.window_difference > o.window_tolerance)
      m.reason = fmt::format("windows of {} and {} sites differ by {:.2e} > {:.0e}", r.sites, r.check_sites,
                             m.window_difference, o.window_tolerance);
    m.certified = m.reason.empty();
    r.localized.push_back(m);
  }
  r.products = product.products();
  // The verdict from the certified multipliers.
  std::vector<Complex> certified;
  bool all_certified = true;
  for (const WindowedMultiplier& m : r.localized) {
    if (m.certified) certified.push_back(m.lambda);
    all_certified = all_certified && m.certified;
  }
  dark::FloquetOptions classify;
  classify.unit_tolerance = o.unit_tolerance;
  classify.symmetry_multipliers = 0;
  const dark::FloquetResult verdict = classify_multipliers(certified, classify);
  if (verdict.real_instability || verdict.period_doubling || verdict.oscillatory)
    r.verdict = verdict;  // a certified instability
  else if (Index(r.trivial.size()) != trivial)
    r.verdict_reason = fmt::format("{} of the {} trivial +1 multipliers found within {:.0e}", r.trivial.size(), trivial,
                                   o.trivial_tolerance);
  else if (!all_certified)
    r.verdict_reason = "not every localized multiplier listed is certified";
  else if (r.max_extended_modulus > 1.0 + o.unit_tolerance)
    r.verdict_reason = fmt::format("an extended window mode has |lambda| = {:.9f} > 1", r.max_extended_modulus);
  else
    r.verdict = verdict;  // stable: the unlisted localized ones have |lambda| <= the last listed <= 1 + tol
  r.certify_seconds = seconds_since(certify_start);
  return r;
}

}  // namespace lrchain::sim::bright
