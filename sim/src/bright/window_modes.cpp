// Window eigenpairs, their split and full-lattice certification (window_modes.hpp).
#include "lrchain/sim/bright/window_modes.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <optional>

#include <Eigen/Eigenvalues>
#include <fmt/format.h>

#include "lrchain/errors.hpp"

namespace lrchain::sim::bright {

namespace {

using Complex = std::complex<double>;

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

}  // namespace

Index ring_distance(Index a, Index b, Index n) {
  const Index d = std::abs(a - b) % n;
  return std::min(d, n - d);
}

Index full_site(Index center, Index width, Index i, Index n) { return ((center - width / 2 + i) % n + n) % n; }

WindowSpectrum window_eigenpairs(const Eigen::MatrixXd& monodromy) {
  Eigen::EigenSolver<Eigen::MatrixXd> solver(monodromy, true);
  if (solver.info() != Eigen::Success) throw NumericalFailure("windowed Floquet: eigenvalue solver failed");
  return {solver.eigenvalues(), solver.eigenvectors()};
}

WindowModes split_window_modes(const WindowSpectrum& spectrum, Index width, Index full_sites, Index trivial_expected,
                               const WindowedFloquetOptions& o) {
  WindowModes r;
  const Index values = spectrum.values.size();
  std::vector<Index> order(static_cast<std::size_t>(values));
  std::iota(order.begin(), order.end(), Index(0));
  std::sort(order.begin(), order.end(),
            [&](Index a, Index b) { return std::abs(spectrum.values[a] - 1.0) < std::abs(spectrum.values[b] - 1.0); });
  const Index trivial = std::min<Index>(values, trivial_expected);
  for (Index k = 0; k < values; ++k) {
    const Index i = order[std::size_t(k)];
    if (k < trivial && std::abs(spectrum.values[i] - 1.0) <= o.trivial_tolerance) {
      r.trivial.push_back(spectrum.values[i]);
      continue;
    }
    if (width < full_sites && edge_fraction(spectrum.vectors.col(i), width, o.margin) > o.edge_weight)
      r.max_extended_modulus = std::max(r.max_extended_modulus, std::abs(spectrum.values[i]));
    else
      r.localized.push_back(i);
  }
  std::stable_sort(r.localized.begin(), r.localized.end(),
                   [&](Index a, Index b) { return std::abs(spectrum.values[a]) > std::abs(spectrum.values[b]); });
  return r;
}

double monodromy_residual(const dark::MonodromyProduct& product, const Eigen::VectorXcd& v, Complex lambda) {
  const Eigen::VectorXd re = v.real(), im = v.imag();
  Eigen::VectorXd mre(re.size()), mim = Eigen::VectorXd::Zero(im.size());
  product.apply(re.data(), mre.data());
  if (im.norm() > 0) product.apply(im.data(), mim.data());
  Eigen::VectorXcd mv(v.size());
  mv.real() = mre;
  mv.imag() = mim;
  return (mv - lambda * v).norm() / v.norm();
}

std::vector<WindowedMultiplier> certify_localized(const dark::MonodromyProduct& product, const WindowSpectrum& first,
                                                  const WindowSpectrum& second, const std::vector<Index>& localized,
                                                  Index center, Index width, Index check_width, Index full_sites,
                                                  const WindowedFloquetOptions& o) {
  std::vector<WindowedMultiplier> r;
  for (Index i : localized) {
    WindowedMultiplier m;
    m.lambda = first.values[i];
    m.window_difference = (second.values.array() - m.lambda).abs().minCoeff();
    // A conjugate of an earlier multiplier has the conjugate eigenvector: the same residual.
    const auto conjugate = std::find_if(r.begin(), r.end(), [&](const WindowedMultiplier& e) {
      return m.lambda.imag() != 0 && std::abs(e.lambda - std::conj(m.lambda)) <= 1e-12 * std::abs(m.lambda);
    });
    m.residual = conjugate != r.end() ? conjugate->residual
                                      : std::optional(monodromy_residual(
                                            product, embed(first.vectors.col(i), center, width, full_sites), m.lambda));
    if (*m.residual > o.residual_tolerance)
      m.reason = fmt::format("full-lattice residual {:.2e} > {:.0e}", *m.residual, o.residual_tolerance);
    else if (m.window_difference > o.window_tolerance)
      m.reason = fmt::format("windows of {} and {} sites differ by {:.2e} > {:.0e}", width, check_width,
                             m.window_difference, o.window_tolerance);
    m.certified = m.reason.empty();
    r.push_back(m);
  }
  return r;
}

}  // namespace lrchain::sim::bright
