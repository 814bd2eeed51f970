#pragma once
// The window steps shared by the windowed Floquet of bright (windowed_floquet.hpp) and dark
// (dark/windowed_dark_floquet.hpp) breathers: the eigenpairs of a window ring's dense monodromy, their
// split into trivial (+1), localized (little weight on the window's outer margins) and extended
// modes, and the certification of localized ones by their residual ||M v - lambda v|| / ||v|| on the
// full lattice (the window eigenvector embedded about the window's centre).
#include <complex>
#include <vector>

#include <Eigen/Dense>

#include "lrchain/index.hpp"
#include "lrchain/sim/bright/windowed_floquet.hpp"
#include "lrchain/sim/dark/monodromy_product.hpp"

namespace lrchain::sim::bright {

// Distance of sites a and b on a ring of n sites.
Index ring_distance(Index a, Index b, Index n);

// Full-ring site of window site i (window of `width` sites centred on `center`).
Index full_site(Index center, Index width, Index i, Index n);

// The eigenpairs of a window's dense monodromy (NumericalFailure when the eigensolver fails).
struct WindowSpectrum {
  Eigen::VectorXcd values;
  Eigen::MatrixXcd vectors;
};
WindowSpectrum window_eigenpairs(const Eigen::MatrixXd& monodromy);

// The window's modes: the `trivial_expected` nearest +1 within trivial_tolerance, the localized ones
// (indices into spectrum, largest modulus first; all of them when the window is the whole ring) and
// the largest modulus among the extended ones.
struct WindowModes {
  std::vector<std::complex<double>> trivial;
  std::vector<Index> localized;
  double max_extended_modulus = 0;
};
WindowModes split_window_modes(const WindowSpectrum& spectrum, Index width, Index full_sites, Index trivial_expected,
                               const WindowedFloquetOptions& o);

// The localized multipliers `localized` of `first`, each with its window difference to `second` and its
// full-lattice residual (product on the full ring), certified when both are within tolerance.
std::vector<WindowedMultiplier> certify_localized(const dark::MonodromyProduct& product, const WindowSpectrum& first,
                                                  const WindowSpectrum& second, const std::vector<Index>& localized,
                                                  Index center, Index width, Index check_width, Index full_sites,
                                                  const WindowedFloquetOptions& o);

// ||M v - lambda v|| / ||v|| with M v from real products (M real: M v = M Re v + i M Im v).
double monodromy_residual(const dark::MonodromyProduct& product, const Eigen::VectorXcd& v, std::complex<double> lambda);

}  // namespace lrchain::sim::bright
