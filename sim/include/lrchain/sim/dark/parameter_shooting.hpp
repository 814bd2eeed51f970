#pragma once
// A model file's dark-breather shooting continued in one of its parameters at a fixed omega_b (issue
// 27: `dark continue --parameter C`, down to the anti-continuum limit C = 0): the second argument of
// evaluate, measure, ... is that parameter's value. The lattice (DarkShooting, and its reflection
// family when given) is rebuilt whenever the value changes; dF/dparameter by a central difference of
// two orbit integrations (step 1e-6 max(1, |p|): relative error ~1e-10 of a smooth flow, far below what
// the chord corrector and the tangent need), one-sided of second order where p - h or p + h leaves
// the parameter's range (at C = 0 no orbit is integrated at C < 0).
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "lrchain/model.hpp"
#include "lrchain/sim/dark/lattice_reflection.hpp"
#include "lrchain/sim/dark/shooting.hpp"
#include "lrchain/sim/dark/symmetric_shooting.hpp"

namespace lrchain::sim::dark {

struct ParameterShootingSetup {
  const lrchain_lattice_kernels* kernels = nullptr;
  std::vector<double> parameters;  // the model file's order
  Index index = 0;                 // of the continued parameter
  ModelParameter range;            // its name and valid range
  Index sites = 0;
  bool mean_flow = false;
  ShootingMode mode = ShootingMode::reversible;
  ContactIntegrationOptions integration;
  std::optional<LatticeReflection> reflection;  // the family imposed, if any
  double omega_b = 0;
};

class ParameterShooting : public DarkShootingProblem {
 public:
  explicit ParameterShooting(ParameterShootingSetup setup);
  ~ParameterShooting() override;
  Index unknowns() const override;
  Eigen::VectorXd z_from_unknowns(const Eigen::VectorXd& q) const override;
  void evaluate(const Eigen::VectorXd& q, double value, Eigen::VectorXd& residual, Eigen::MatrixXd* jacobian,
                Eigen::MatrixXd* propagator = nullptr) const override;
  void jacobian_and_floquet(const Eigen::VectorXd& q, double value, Eigen::VectorXd& residual,
                            Eigen::MatrixXd& jacobian, FloquetResult* floquet) const override;
  void measure(const Eigen::VectorXd& z0, double value, DarkMeasures& out) const override;
  std::optional<Index> contact_changes_per_period(const Eigen::VectorXd& z0, double value) const override;
  std::string parameter_name() const override { return setup_.range.name; }
  double omega_b_at(double) const override { return setup_.omega_b; }
  bool parameter_allowed(double value) const override { return setup_.range.contains(value); }

 private:
  // The shooting problem at `value` (rebuilt when the value changes).
  const DarkShootingProblem& at(double value) const;
  ParameterShootingSetup setup_;
  mutable double value_ = 0;
  mutable std::unique_ptr<DarkShooting> shooting_;
  mutable std::unique_ptr<SymmetricDarkShooting> family_;
};

}  // namespace lrchain::sim::dark
