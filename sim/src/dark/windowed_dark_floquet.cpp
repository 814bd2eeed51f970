// Windowed Floquet multipliers of a dark breather and the background's Floquet-Bloch spectrum
// (windowed_dark_floquet.hpp).
#include "lrchain/sim/dark/windowed_dark_floquet.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <memory>
#include <numbers>
#include <vector>

#include <Eigen/Eigenvalues>
#include <fmt/format.h>

#include "lrchain/sim/bright/window_modes.hpp"
#include "lrchain/sim/dark/monodromy_product.hpp"

namespace lrchain::sim::dark {

namespace {

using Complex = std::complex<double>;
using bright::full_site;
using bright::ring_distance;

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// The ring of `sites` sites of the window lattice.
std::unique_ptr<DarkShooting> lattice_ring(const bright::WindowLattice& lattice, Index sites) {
  return std::make_unique<DarkShooting>(*lattice.kernels, lattice.parameters, sites, lattice.mean_flow,
                                        ShootingMode::reversible, ContactIntegrationOptions{}, lattice.contacts);
}

// The 2-site cell (fields x 2) repeated over a ring of `sites` (even) sites, field-major.
Eigen::VectorXd tile(const Eigen::MatrixXd& cell, Index sites) {
  const Index fields = cell.rows();
  Eigen::VectorXd z(fields * sites);
  for (Index f = 0; f < fields; ++f)
    for (Index i = 0; i < sites; ++i) z[f * sites + i] = cell(f, i % 2);
  return z;
}

// Bloch monodromy B(Q) = sum_d G(d) exp(-i Q d) of the 2-site-periodic background from the monodromy
// columns of one cell's 4 F unknowns on a ring of 2 m sites (d: the cell offset, nearest image), into B.
void bloch_monodromy(const Eigen::MatrixXd& columns, Index fields, Index ring, double Q, Eigen::MatrixXcd& B) {
  const Index cells = ring / 2, positions = fields * ring;
  B.setZero();
  for (Index c = 0; c < cells; ++c) {
    const double d = double(c <= cells / 2 ? c : c - cells);
    const Complex phase = std::polar(1.0, -Q * d);
    for (Index block = 0; block < 2; ++block)
      for (Index f = 0; f < fields; ++f)
        for (Index s = 0; s < 2; ++s)
          B.row((block * fields + f) * 2 + s) += phase * columns.row(block * positions + f * ring + 2 * c + s);
  }
}

// The ring vector of Bloch amplitude u (4 F entries) at cell wavenumber Q.
Eigen::VectorXcd bloch_vector(const Eigen::VectorXcd& u, Index fields, Index ring, double Q) {
  const Index positions = fields * ring;
  Eigen::VectorXcd v(2 * positions);
  for (Index c = 0; c < ring / 2; ++c)
    for (Index block = 0; block < 2; ++block)
      for (Index f = 0; f < fields; ++f)
        for (Index s = 0; s < 2; ++s)
          v[block * positions + f * ring + 2 * c + s] = u[(block * fields + f) * 2 + s] * std::polar(1.0, Q * double(c));
  return v;
}

// The background plane wave's Floquet-Bloch multipliers from the far-field cell of Z(0).
BackgroundSpectrum background_spectrum(const bright::WindowLattice& lattice, const Eigen::MatrixXd& far_cell,
                                       double omega_b, const WindowedDarkFloquetOptions& o) {
  BackgroundSpectrum r;
  const Index fields = far_cell.rows();
  // The exact plane wave on a 10-site ring (Newton keeps the 2-site period of its seed).
  const auto small = lattice_ring(lattice, 10);
  const NewtonResult wave = newton_solve(*small, tile(far_cell, 10), omega_b, o.newton);
  if (!wave.converged) {
    r.reason = "the background plane wave did not converge on a 10-site ring: " + wave.failure;
    return r;
  }
  r.newton_residual = wave.history.back().residual;
  Eigen::MatrixXd cell(fields, 2);
  for (Index f = 0; f < fields; ++f) cell.row(f) << wave.q[f * 10], wave.q[f * 10 + 1];
  r.amplitude = cell.cwiseAbs().maxCoeff();
  r.cell = cell;
  // Monodromy columns of one cell on rings of doubling size until they fit.
  std::unique_ptr<DarkShooting> ring;
  std::unique_ptr<MonodromyProduct> product;
  Eigen::MatrixXd columns;
  for (Index sites = o.background_sites;; sites *= 2) {
    ring = lattice_ring(lattice, sites);
    product = std::make_unique<MonodromyProduct>(*ring, tile(cell, sites), omega_b);
    const Index positions = fields * sites;
    columns.resize(2 * positions, 4 * fields);
    r.truncation = 0;
    Eigen::VectorXd e(2 * positions), y(2 * positions);
    for (Index block = 0; block < 2; ++block)
      for (Index f = 0; f < fields; ++f)
        for (Index s = 0; s < 2; ++s) {
          e.setZero();
          e[block * positions + f * sites + s] = 1;
          product->apply(e.data(), y.data());
          double far = 0;
          for (Index i = 0; i < 2 * positions; ++i)
            if (ring_distance(i % sites, 0, sites) >= sites / 4) far += y[i] * y[i];
          r.truncation = std::max(r.truncation, std::sqrt(far) / y.norm());
          columns.col((block * fields + f) * 2 + s) = y;
        }
    r.ring_sites = sites;
    if (r.truncation <= o.truncation_tolerance || 2 * sites > o.background_cap) break;
  }
  if (r.truncation > o.truncation_tolerance) {
    r.reason = fmt::format("the background's monodromy columns keep {:.1e} of their norm beyond a quarter of a "
                           "{}-site ring (> {:.0e})", r.truncation, r.ring_sites, o.truncation_tolerance);
    return r;
  }
  // Every sampled wavenumber, and the ring's own grid 2 pi k / cells (certified by residual).
  std::vector<Complex> off_circle;
  const Index cells = r.ring_sites / 2;
  r.wavenumbers = o.wavenumbers;
  Eigen::ComplexEigenSolver<Eigen::MatrixXcd> solver;
  // At Q = 0 the trivial multipliers (phase, and the mean strain in strain form) form Jordan blocks at
  // +1 that an eigensolver splits by up to eps^(1/4): the nearest +1 are left out there.
  const Index trivial = lattice.mean_flow ? 4 : 2;
  Eigen::MatrixXcd B(4 * fields, 4 * fields);
  std::vector<Index> order(std::size_t(4 * fields));
  auto scan = [&](double Q, bool grid, Eigen::VectorXcd* u, Complex* leading) {
    bloch_monodromy(columns, fields, r.ring_sites, Q, B);
    solver.compute(B, grid);
    const Eigen::VectorXcd& values = solver.eigenvalues();
    for (Index i = 0; i < values.size(); ++i) order[std::size_t(i)] = i;
    std::sort(order.begin(), order.end(),
              [&](Index a, Index b) { return std::abs(values[a] - 1.0) < std::abs(values[b] - 1.0); });
    for (Index k = Q == 0 ? trivial : 0; k < values.size(); ++k) {
      const Index i = order[std::size_t(k)];
      const Complex l = values[i];
      if (!grid && std::abs(l) > r.max_modulus) r.max_modulus = std::abs(l), r.max_wavenumber = Q / 2;
      if (!grid && std::abs(l) > 1 + o.window.unit_tolerance) off_circle.push_back(l);
      if (grid && std::abs(l) > std::abs(*leading)) *leading = l, *u = solver.eigenvectors().col(i);
    }
  };
  for (Index k = 0; k < o.wavenumbers; ++k)
    scan(std::numbers::pi * double(k) / double(o.wavenumbers - 1), false, nullptr, nullptr);
  Eigen::VectorXcd u, best_u;
  Complex leading = 0;
  double best_Q = 0;
  for (Index k = 0; 2 * k <= cells; ++k) {
    const double Q = 2 * std::numbers::pi * double(k) / double(cells);
    const Complex before = leading;
    scan(Q, true, &u, &leading);
    if (leading != before) best_u = u, best_Q = Q;
  }
  r.ring_leading = leading;
  r.ring_residual = bright::monodromy_residual(*product, bloch_vector(best_u, fields, r.ring_sites, best_Q), leading);
  if (!off_circle.empty()) {
    FloquetOptions classify;
    classify.unit_tolerance = o.window.unit_tolerance;
    classify.symmetry_multipliers = 0;
    r.unstable = classify_multipliers(off_circle, classify);
  }
  return r;
}

// The window ring of `width` sites about `center` with the breather solved on it by Newton from Z(0)
// restricted to it; its monodromy's eigenpairs.
struct SolvedWindow {
  NewtonResult newton;
  bright::WindowSpectrum spectrum;
};
SolvedWindow solve_window(const bright::WindowLattice& lattice, const Eigen::VectorXd& z0, Index full_sites,
                          Index center, Index width, double omega_b, const NewtonOptions& newton) {
  const Index fields = z0.size() / full_sites;
  Eigen::VectorXd zw(fields * width);
  for (Index f = 0; f < fields; ++f)
    for (Index i = 0; i < width; ++i) zw[f * width + i] = z0[f * full_sites + full_site(center, width, i, full_sites)];
  const auto window = lattice_ring(lattice, width);
  SolvedWindow r;
  r.newton = newton_solve(*window, zw, omega_b, newton);
  if (r.newton.converged) r.spectrum = bright::window_eigenpairs(window->monodromy(r.newton.q, omega_b));
  return r;
}

// The smallest odd number >= x.
Index odd_at_least(Index x) { return x % 2 == 1 ? x : x + 1; }

}  // namespace

WindowedDarkFloquet windowed_dark_floquet(const DarkShooting& shooting, const bright::WindowLattice& lattice,
                                          const Eigen::VectorXd& z0, double omega_b,
                                          const WindowedDarkFloquetOptions& o) {
  const auto start = std::chrono::steady_clock::now();
  WindowedDarkFloquet r;
  bright::WindowedFloquet& w = r.window;
  const bright::WindowedFloquetOptions& ow = o.window;
  const Index n = shooting.sites(), fields = z0.size() / n;
  w.full_sites = n;
  // The far field: the two sites farthest from the dip (the dip: where Z(0) leaves the two values of
  // the background most; first from the far field of the seed's layout, the dip at the ring's middle).
  auto far_cell = [&](Index dip) {
    Eigen::MatrixXd cell(fields, 2);
    const Index a = (dip + n / 2) % n;
    for (Index f = 0; f < fields; ++f) cell.row(f) << z0[f * n + a], z0[f * n + (a + 1) % n];
    return cell;
  };
  auto deviation = [&](const Eigen::MatrixXd& cell) {
    Eigen::VectorXd d(n);
    for (Index s = 0; s < n; ++s) {
      double nearest = INFINITY;
      for (Index p = 0; p < 2; ++p) {
        double m = 0;
        for (Index f = 0; f < fields; ++f) m = std::max(m, std::abs(z0[f * n + s] - cell(f, p)));
        nearest = std::min(nearest, m);
      }
      d[s] = nearest;
    }
    return d;
  };
  Eigen::VectorXd d = deviation(far_cell((n - 1) / 2));
  d.maxCoeff(&w.center);
  const Eigen::MatrixXd cell = far_cell(w.center);
  d = deviation(cell);
  d.maxCoeff(&w.center);
  const double amplitude = cell.cwiseAbs().maxCoeff();
  // (b) the continuous spectrum: the background's own multipliers.
  r.background = background_spectrum(lattice, cell, omega_b, o);
  r.background_seconds = seconds_since(start);
  // (a) the localized modes: the window about the dip.
  const auto window_start = std::chrono::steady_clock::now();
  // The core: out from the dip until the deviation falls below fraction x amplitude, or below 10 x its
  // median over the ring where the far field's own error (the solve's, ~ its tolerance times the
  // Jacobian's condition) is larger than that.
  Eigen::VectorXd sorted = d;
  std::sort(sorted.data(), sorted.data() + n);
  const double threshold = std::max(ow.fraction * amplitude, 10 * sorted[n / 2]);
  Index half = 0;
  while (half < n / 2 && std::max(d[(w.center + half) % n], d[(w.center - half + n) % n]) > threshold) ++half;
  w.sites = std::min({n, odd_at_least(ow.cap), std::max<Index>(9, 2 * (half + ow.margin) + 1)});
  // Widened (x2, to the cap) while it has extended modes off the unit circle on a stable background:
  // a weakly localized instability (a dip's translation mode near the continuum) then fits a wider one.
  SolvedWindow first, second;
  Index trivial = 0;
  bright::WindowModes modes;
  for (;;) {
    w.check_sites = std::min(n, odd_at_least(Index(std::ceil(1.5 * double(w.sites)))));
    first = solve_window(lattice, z0, n, w.center, w.sites, omega_b, o.newton);
    r.window_newton_iterations = Index(first.newton.history.size()) - 1;
    r.window_newton_residual = first.newton.history.empty() ? NAN : first.newton.history.back().residual;
    if (first.newton.converged) second = solve_window(lattice, z0, n, w.center, w.check_sites, omega_b, o.newton);
    if (!first.newton.converged || !second.newton.converged) {
      w.verdict_reason = fmt::format("the breather did not converge on the {}-site window: {}",
                                     first.newton.converged ? w.check_sites : w.sites,
                                     first.newton.converged ? second.newton.failure : first.newton.failure);
      r.verdict_reason = w.verdict_reason;
      if (r.background.unstable && r.background.ring_residual <= ow.residual_tolerance) {
        r.verdict = r.background.unstable;  // the background's certified instability decides alone
        w.verdict = r.verdict;
        w.verdict_reason = r.verdict_reason = "";
      }
      w.window_seconds = seconds_since(window_start);
      return r;
    }
    trivial = std::min<Index>(first.spectrum.values.size(), lattice.mean_flow ? 4 : 2);
    modes = bright::split_window_modes(first.spectrum, w.sites, n, trivial, ow);
    const Index cap = std::min(n, odd_at_least(ow.cap));
    if (!(r.background.reason.empty() && !r.background.unstable &&
          modes.max_extended_modulus > 1.0 + ow.unit_tolerance && w.sites < cap))
      break;
    w.sites = std::min(cap, 2 * w.sites + 1);
  }
  w.trivial = modes.trivial;
  w.max_extended_modulus = modes.max_extended_modulus;
  w.localized_found = Index(modes.localized.size());
  if (Index(modes.localized.size()) > ow.count) modes.localized.resize(std::size_t(ow.count));
  w.window_seconds = seconds_since(window_start);
  const auto certify_start = std::chrono::steady_clock::now();
  const MonodromyProduct product(shooting, z0, omega_b);
  w.localized = bright::certify_localized(product, first.spectrum, second.spectrum, modes.localized, w.center, w.sites,
                                          w.check_sites, n, ow);
  w.products = product.products();
  w.certify_seconds = seconds_since(certify_start);
  // The verdict: certified instabilities (localized, background), else stable only when nothing is open.
  std::vector<Complex> certified;
  bool all_certified = true;
  for (const bright::WindowedMultiplier& m : w.localized) {
    if (m.certified) certified.push_back(m.lambda);
    all_certified = all_certified && m.certified;
  }
  const bool background_certified =
      r.background.reason.empty() && r.background.ring_residual <= ow.residual_tolerance;
  if (r.background.unstable && background_certified)
    certified.insert(certified.end(), r.background.unstable->multipliers.begin(),
                     r.background.unstable->multipliers.end());
  FloquetOptions classify;
  classify.unit_tolerance = ow.unit_tolerance;
  classify.symmetry_multipliers = 0;
  const FloquetResult verdict = classify_multipliers(certified, classify);
  if (verdict.real_instability || verdict.period_doubling || verdict.oscillatory)
    r.verdict = verdict;
  else if (!r.background.reason.empty())
    r.verdict_reason = "the background's spectrum is not known: " + r.background.reason;
  else if (!background_certified)
    r.verdict_reason = fmt::format("the background's leading Bloch multiplier has residual {:.2e} > {:.0e}",
                                   r.background.ring_residual, ow.residual_tolerance);
  else if (Index(w.trivial.size()) != trivial)
    r.verdict_reason = fmt::format("{} of the {} trivial +1 multipliers found within {:.0e}", w.trivial.size(), trivial,
                                   ow.trivial_tolerance);
  else if (!all_certified)
    r.verdict_reason = "not every localized multiplier listed is certified";
  else if (w.max_extended_modulus > 1.0 + ow.unit_tolerance)
    r.verdict_reason = fmt::format(
        "an extended mode of the {}-site window (the widest tried) has |lambda| = {:.9f} > 1 while the background's "
        "multipliers lie on the unit circle: an instability whose eigenvector does not fit the window (a finite-size "
        "instability of a ring, set by its size, or a mode localized more weakly than the window), not certifiable "
        "for the {}-site ring from the window", w.sites, w.max_extended_modulus, n);
  else
    r.verdict = verdict;  // stable: localized ones certified on the circle, the continuous spectrum on it
  w.verdict = r.verdict;  // the window's record carries the breather's verdict
  w.verdict_reason = r.verdict_reason;
  return r;
}

}  // namespace lrchain::sim::dark
