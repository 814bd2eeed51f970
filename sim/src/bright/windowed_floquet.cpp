// Windowed Floquet multipliers of a bright breather, certified by full-lattice residuals
// (windowed_floquet.hpp).
#include "lrchain/sim/bright/windowed_floquet.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>

#include <fmt/format.h>

#include "lrchain/sim/bright/window_modes.hpp"
#include "lrchain/sim/dark/monodromy_product.hpp"

namespace lrchain::sim::bright {

namespace {

using Complex = std::complex<double>;

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// The eigenpairs of the dense monodromy of the window ring of `width` sites about `center`, the
// breather's positions restricted to it (field-major), velocities zero as on the full ring.
WindowSpectrum window_spectrum(const WindowLattice& lattice, const Eigen::VectorXd& z0, Index full_sites, Index center,
                               Index width, double omega_b) {
  const Index fields = z0.size() / full_sites;
  Eigen::VectorXd zw(fields * width);
  for (Index f = 0; f < fields; ++f)
    for (Index i = 0; i < width; ++i) zw[f * width + i] = z0[f * full_sites + full_site(center, width, i, full_sites)];
  const dark::DarkShooting window(*lattice.kernels, lattice.parameters, width, lattice.mean_flow,
                                  dark::ShootingMode::reversible, {}, lattice.contacts);
  return window_eigenpairs(window.monodromy(zw, omega_b));
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
  const Index trivial = std::min<Index>(first.values.size(), lattice.mean_flow ? 4 : 2);
  WindowModes modes = split_window_modes(first, r.sites, n, trivial, o);
  r.trivial = modes.trivial;
  r.max_extended_modulus = modes.max_extended_modulus;
  std::vector<Index>& localized = modes.localized;
  r.localized_found = Index(localized.size());
  if (Index(localized.size()) > o.count) localized.resize(std::size_t(o.count));
  r.window_seconds = seconds_since(start);
  // Certification on the full lattice.
  const auto certify_start = std::chrono::steady_clock::now();
  const dark::MonodromyProduct product(shooting, z0, omega_b);
  r.localized = certify_localized(product, first, second, localized, r.center, r.sites, r.check_sites, n, o);
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
