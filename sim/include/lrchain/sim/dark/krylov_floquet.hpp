#pragma once
// The leading Floquet multipliers of a breather of any model lattice (shooting.hpp) without the
// monodromy matrix: an implicitly restarted Arnoldi method (Spectra's GenEigsSolver, Krylov-Schur-like
// restarts of ARPACK) on monodromy-vector products M v, each one tangent replayed with the orbit on
// its recorded steps over one period T_b. For large lattices, where the dense 2P x 2P monodromy
// (dark/floquet.hpp, bright/bright_floquet.hpp) costs O(N^3) time and O(N^2) memory; the dense path
// remains the check on small ones.
#include <complex>
#include <vector>

#include <Eigen/Dense>

#include "lrchain/index.hpp"
namespace lrchain::sim::dark {

class DarkShooting;  // shooting.hpp

struct KrylovFloquetOptions {
  Index count = 20;          // multipliers wanted, largest modulus first (>= 1)
  Index subspace = 0;        // Arnoldi vectors kept; 0: max(2 count + 1, count + 20)
  Index max_restarts = 100;  // Arnoldi restarts before giving up (a stable breather's multipliers crowd the unit
                             // circle: there only some of them converge, reported as such)
  double tolerance = 1e-10;  // a Ritz value is converged when its residual <= tolerance |lambda|
};

struct KrylovFloquetResult {
  std::vector<std::complex<double>> multipliers;  // the converged ones, |lambda| descending
  Index requested = 0;
  Index restarts = 0;  // Arnoldi restarts used
  Index products = 0;  // monodromy-vector products
  bool converged = false;  // all `requested` converged
};

// The `count` largest-modulus eigenvalues of the monodromy M = dZ(T_b)/dZ(0) of the orbit from
// [z0, 0]. Throws InvalidParameter("floquet_count") unless 1 <= count <= 2 positions() - 2.
KrylovFloquetResult leading_multipliers(const DarkShooting& shooting, const Eigen::VectorXd& z0, double omega_b,
                                        const KrylovFloquetOptions& options = {});

}  // namespace lrchain::sim::dark
