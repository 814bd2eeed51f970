#pragma once
// Shooting of a model file's dark breather restricted to its reflection family (issue 27,
// continuation; lattice_reflection.hpp), as the resonant chain's site and bond families
// (resonant_chain_shooting.hpp):
//  * Z(t) = R Z(t): unknowns Z(0) in the R-even subspace, residual the R-even part of Zdot(T_b/2);
//  * Z(t + T_b/2) = R Z(t): unknowns all of Z(0), residual (I - R) Z(T_b/4) and (I + R) Zdot(T_b/4)
//    (time reversal and the reflection close the orbit after a quarter period).
// Translation-invariant models keep the C_x row (eq:center at the far site) while the conserved total
// strain is free in the family (the first field's sign +1); with sign -1 the reflection fixes it to 0.
// Floquet multipliers, measures and contact changes are those of the underlying DarkShooting.
#include <Eigen/Dense>

#include "lrchain/sim/dark/lattice_reflection.hpp"
#include "lrchain/sim/dark/shooting.hpp"

namespace lrchain::sim::dark {

class SymmetricDarkShooting : public DarkShootingProblem {
 public:
  // `shooting` (its orbit and model) must outlive this object.
  SymmetricDarkShooting(const DarkShooting& shooting, LatticeReflection reflection);
  const LatticeReflection& reflection() const { return reflection_; }
  Index unknowns() const override { return Index(basis_.cols()); }
  Eigen::VectorXd z_from_unknowns(const Eigen::VectorXd& q) const override { return basis_ * q; }
  // Least-squares projection of Z(0) onto the family's unknowns.
  Eigen::VectorXd unknowns_from_z(const Eigen::VectorXd& z0) const { return basis_.transpose() * z0; }

  void evaluate(const Eigen::VectorXd& q, double omega_b, Eigen::VectorXd& residual, Eigen::MatrixXd* jacobian,
                Eigen::MatrixXd* propagator = nullptr) const override;
  void jacobian_and_floquet(const Eigen::VectorXd& q, double omega_b, Eigen::VectorXd& residual,
                            Eigen::MatrixXd& jacobian, FloquetResult* floquet) const override;
  void measure(const Eigen::VectorXd& z0, double omega_b, DarkMeasures& out) const override;
  std::optional<Index> contact_changes_per_period(const Eigen::VectorXd& z0, double omega_b) const override;

 private:
  const DarkShooting& shooting_;
  LatticeReflection reflection_;
  Eigen::MatrixXd basis_;                 // Z(0) = basis_ q
  Eigen::MatrixXd even_, odd_;            // R-even and R-odd orthonormal bases
  bool center_row_ = false;               // the C_x row (translation-invariant, total strain free)
};

}  // namespace lrchain::sim::dark
