#pragma once
// Floquet multipliers of a stationary dark breather (Sec. 5.4): eigenvalues of the monodromy
// matrix of the variational equations of eq:Hertzd0S over one period T_b (Eigen), classified as
// stable / real instability / period doubling / oscillatory instability.
#include <complex>
#include <string>
#include <vector>

#include <Eigen/Dense>

#include "lrchain/index.hpp"
#include "lrchain/sim/dark/resonant_chain_shooting.hpp"

namespace lrchain::sim::dark {

struct FloquetOptions {
  double unit_tolerance = 1e-6;      // |lambda| > 1 + tol counts as unstable
  double real_tolerance = 1e-7;      // |Im lambda| <= tol |lambda| counts as real
  double symmetry_tolerance = 2e-3;  // the 4 multipliers this close to +1 are symmetry modes
  Index symmetry_multipliers = 4;      // phase/frequency and zero-mode (sum of strains) Jordan blocks
};

struct FloquetResult {
  std::vector<std::complex<double>> multipliers;
  double max_modulus = 0;          // over all multipliers
  double max_real = 1;             // largest |lambda| of real lambda > 1 (1 if none)
  double max_period_doubling = 1;  // largest |lambda| of real lambda < -1 (1 if none)
  double max_oscillatory = 1;      // largest |lambda| of non-real lambda off the circle (1 if none)
  Index near_one = 0;                // multipliers within symmetry_tolerance of +1
  double pairing_defect = 0;       // max_i min_j |lambda_j - 1/conj(lambda_i)| / max(1,|1/lambda_i|)
  double conjugation_defect = 0;   // max_i min_j |lambda_j - conj(lambda_i)|
  double log_det = 0;              // sum log|lambda| (0 for the volume-preserving flow)
  bool real_instability = false, period_doubling = false, oscillatory = false;
  std::string kind() const;        // "stable" or e.g. "real+oscillatory"
};

// Fast path from the shooting propagator of the reversible mode (one half or one quarter period)
// using the time-reversal (and, bond-centred, reflection) symmetry of the orbit:
//   site: M = S A^{-1} S A with A = Phi(T_b/2), S = diag(I, -I) (x, y even; velocities odd);
//   bond: M = (R M_h)^2, R M_h = S X, X = A^{-1} (R S) A with A = Phi(T_b/4).
// For M = S X with involutions S, X, (M + M^{-1})/2 = diag(P, -U) where P is the (Z, Z) block of X,
// so the multipliers follow from the 2N x 2N eigenproblem of P: lambda = mu +- sqrt(mu^2 - 1).
// The (lambda, 1/lambda) pairing then holds by construction; use floquet_from_monodromy on an
// independently integrated full-period monodromy to check it.
FloquetResult floquet_reversible(const ResonantChainShooting& shooting, const Eigen::MatrixXd& propagator,
                                 const FloquetOptions& options = {});

// Eigenvalues of a full monodromy matrix (e.g. ResonantChainShooting in full mode).
FloquetResult floquet_from_monodromy(const Eigen::MatrixXd& monodromy,
                                     const FloquetOptions& options = {});

// Classification and structure checks of given multipliers.
FloquetResult classify_multipliers(std::vector<std::complex<double>> multipliers,
                                   const FloquetOptions& options = {});

}  // namespace lrchain::sim::dark
