#pragma once
// Matrix-free Newton (Newton-Krylov) on the reversible shooting of any model lattice (shooting.hpp),
// shared by the dark and the bright breathers: each Newton step solves J dq = -F by GMRES (Eigen's
// unsupported IterativeSolvers) on Jacobian-vector products, one tangent vector integrated with the
// orbit per product, never the full 2P x P propagator. Cost per Newton step O(N) per product.
//
// Preconditioner: the Jacobian probed in a band. J = dZdot(T_b/2)/dZ(0) is the half-period
// propagator of a lattice with nearest-neighbour (or finite-range) coupling; a perturbation at site n
// spreads at the lattice's finite group velocity, so J's entries decay faster than exponentially
// beyond |m - n| ~ v_max T_b/2 (a light cone of a few sites, independent of N). Sites farther apart
// than 2 band + 1 share one probe vector (Curtis-Powell-Reid colouring), so F (2 band + 1) + O(F band)
// tangents give J within the band whatever N; its sparse LU (Eigen SparseLU, O(N band^2)) leaves
// GMRES only the part beyond the band, which does not grow with N: the GMRES iteration count stays
// flat in N. The probed Jacobian of the seed is kept while GMRES converges within a few iterations
// and probed again at the current point when it needs more (max_preconditioned_iterations).
//
// Square system: for strain-form models the dense Newton solves the P velocity rows and the C_x row
// in least squares. The sum of the strain velocities sum_n rdot_n vanishes identically on a ring
// (r_n = u_0[n] - u_0[n-1]), so the velocity row of site 0 of field 0 is minus the sum of the other
// field-0 rows: here it is replaced by the C_x row, a square P x P system with the same zeros.
#include <Eigen/Dense>

#include "lrchain/index.hpp"
#include "lrchain/sim/dark/shooting_problem.hpp"

namespace lrchain::sim::dark {

class DarkShooting;  // shooting.hpp

struct NewtonKrylovOptions {
  NewtonOptions newton;                    // tolerance, iterations, progress: as the dense Newton
  Index band = 12;                         // preconditioner half-width in sites (>= 1)
  double gmres_tolerance = 1e-10;          // GMRES relative residual |J dq + F| / |F|
  Index gmres_max_iterations = 300;        // per Newton step
  Index gmres_restart = 60;                // Krylov vectors kept before a restart
  Index max_preconditioned_iterations = 8; // more GMRES iterations than this: probe J again
};

struct NewtonKrylovStats {
  std::vector<Index> gmres_iterations;  // per Newton step
  Index jacobian_products = 0;          // Jacobian-vector products in GMRES
  Index preconditioner_builds = 0;      // band probings
  Index probe_columns = 0;              // tangents per probing
};

// Newton-Krylov on F(., omega_b) = 0 of a reversible DarkShooting from q0: the same convergence test,
// trivial-state check and failure messages as newton_solve (shooting_problem.hpp). Throws
// std::invalid_argument for a shooting in full mode.
NewtonResult newton_krylov_solve(const DarkShooting& shooting, Eigen::VectorXd q0, double omega_b,
                                 const NewtonKrylovOptions& options, NewtonKrylovStats* stats = nullptr);

}  // namespace lrchain::sim::dark
