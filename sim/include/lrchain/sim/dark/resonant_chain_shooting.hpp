#pragma once
// Shooting formulation of stationary dark breathers of the resonant chain (Sec. 5.3): time-periodic solutions of the
// strain lattice eq:Hertzd0S (periodic ends) with Zdot(0) = 0, as zeros of a residual F(q, omega_b)
// of the unknown initial strains Z(0) = (x(0), y(0)) = B q, with the Jacobian from the
// variational equations integrated with the orbit. See docs/dark-breathers.md.
//
// Families and symmetries (N odd sites, array index i, centre in the middle of the array):
//  * site-centred (n0 = 0 in eq:xy_app): x_i = x_{R(i)}, R(i) = (N - i) mod N, at all times.
//    Unknowns: Z(0) in the R-symmetric subspace (N + 1 of them).
//  * bond-centred (n0 = 1/2): Z(t + T_b/2) = R Z(t), R(i) = (N + 1 - i) mod N (the staggered part
//    is odd, the mean part even about the centre site). Unknowns: all 2N strains.
// Modes:
//  * reversible (default): time reversal makes Z(-t) = Z(t); the orbit has period T_b iff
//    Zdot(T_b/2) = 0 (site family, half a period) and, with the bond symmetry, iff
//    (I - R) Z(T_b/4) = 0 and (I + R) Zdot(T_b/4) = 0 (quarter period).
//  * full: Z(T_b) - Z(0) = 0, Zdot(T_b) = 0 (+ Z(T_b/2) - R Z(0) = 0 for the bond family);
//    least squares. Used to check the reversible formulation.
// In both, one row fixes the conserved zero mode (sum of x + rho y) through the vertical centre
// C_x = (x_0(0) + x_0(T_b/2))/2 = 0 at the far site i = 0 (eq:center, extrema at t = 0, T_b/2).
#include <Eigen/Dense>
#include <optional>
#include <string>
#include <vector>

#include "lrchain/index.hpp"
#include "lrchain/ansatz/dark_breather.hpp"
#include "lrchain/params.hpp"
#include "lrchain/sim/dark/contact_integrator.hpp"
#include "lrchain/sim/dark/shooting_problem.hpp"

namespace lrchain::sim::dark {

class ResonantChainShooting : public DarkShootingProblem {
 public:
  // Throws InvalidParameter("sites") unless sites is odd and >= 9 (staggered waves on a ring).
  ResonantChainShooting(const Params& p, Index sites, DarkCenter center, ShootingMode mode,
               ContactIntegrationOptions integration = {});

  Index sites() const { return sites_; }
  Index unknowns() const override { return basis_.cols(); }
  DarkCenter center() const { return center_; }
  ShootingMode mode() const { return mode_; }
  const Params& params() const { return p_; }
  const ContactIntegrationOptions& integration() const { return integration_; }
  // Reflection of the family: site index i -> R(i).
  Index reflect(Index i) const { return reflection_[static_cast<std::size_t>(i)]; }

  Eigen::VectorXd z_from_unknowns(const Eigen::VectorXd& q) const override { return basis_ * q; }
  // Least-squares projection onto the family's subspace (symmetrises a seed).
  Eigen::VectorXd unknowns_from_z(const Eigen::VectorXd& z0) const { return basis_.transpose() * z0; }

  // Residual F(q, omega_b); if jacobian != nullptr also [dF/dq | dF/domega_b] (unknowns()+1 cols).
  // If propagator != nullptr, all 4N tangent columns are integrated and it receives the state
  // transition matrix over the shooting interval: Phi(T_b/2) (reversible, site), Phi(T_b/4)
  // (reversible, bond) or Phi(T_b) (full mode): the input of the Floquet analysis (floquet.hpp).
  void evaluate(const Eigen::VectorXd& q, double omega_b, Eigen::VectorXd& residual,
                Eigen::MatrixXd* jacobian, Eigen::MatrixXd* propagator = nullptr) const override;
  // Reversible mode: Floquet from the shooting propagator (floquet_reversible); full mode: from
  // the full-period monodromy.
  void jacobian_and_floquet(const Eigen::VectorXd& q, double omega_b, Eigen::VectorXd& residual,
                            Eigen::MatrixXd& jacobian, FloquetResult* floquet) const override;
  void measure(const Eigen::VectorXd& z0, double omega_b, DarkMeasures& out) const override;
  // Time over which the reversible/full shooting integrates: T_b/2, T_b/4 or T_b.
  double shooting_time(double omega_b) const;

 private:
  Params p_;
  Index sites_;
  DarkCenter center_;
  ShootingMode mode_;
  ContactIntegrationOptions integration_;
  std::vector<Index> reflection_;
  Eigen::MatrixXd basis_;       // 2N x k: Z(0) = basis_ q
  Eigen::MatrixXd symmetric_;   // 2N x (N+1): R-even orthonormal basis (x and y fields)
  Eigen::MatrixXd antisymmetric_;  // 2N x (N-1): R-odd orthonormal basis
};

// Seed Z(0) from eq:xy_app at t = 0 on the array (centre in the middle, n_phys = i - (N-1)/2).
Eigen::VectorXd resonant_chain_dark_seed(const DarkBreatherAnsatz& ansatz, DarkCenter center, Index sites);

}  // namespace lrchain::sim::dark
