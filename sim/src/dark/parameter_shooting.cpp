// A model's dark-breather shooting as a function of one of its parameters (parameter_shooting.hpp).
#include "lrchain/sim/dark/parameter_shooting.hpp"

#include <cmath>

#include "lrchain/sim/dark/contact_bonds.hpp"

namespace lrchain::sim::dark {

ParameterShooting::ParameterShooting(ParameterShootingSetup setup) : setup_(std::move(setup)) {
  at(setup_.parameters.at(std::size_t(setup_.index)));
}

ParameterShooting::~ParameterShooting() = default;

const DarkShootingProblem& ParameterShooting::at(double value) const {
  if (!shooting_ || value != value_) {
    family_.reset();
    std::vector<double> parameters = setup_.parameters;
    parameters[std::size_t(setup_.index)] = value;
    ContactBonds bonds = model_contact_bonds(*setup_.kernels, parameters, setup_.mean_flow);
    shooting_ = std::make_unique<DarkShooting>(*setup_.kernels, parameters, setup_.sites, setup_.mean_flow,
                                               setup_.mode, setup_.integration, std::move(bonds));
    if (setup_.reflection) family_ = std::make_unique<SymmetricDarkShooting>(*shooting_, *setup_.reflection);
    value_ = value;
  }
  if (family_) return *family_;
  return *shooting_;
}

Index ParameterShooting::unknowns() const { return at(value_).unknowns(); }

Eigen::VectorXd ParameterShooting::z_from_unknowns(const Eigen::VectorXd& q) const {
  return at(value_).z_from_unknowns(q);
}

// F(q; p) at the fixed omega_b; the last Jacobian column dF/dp = (F(p + h) - F(p - h)) / 2h, or at a
// bound of p's range the one-sided (-3 F(p) + 4 F(p + h) - F(p + 2h)) / 2h (h < 0 at an upper bound),
// both second order, so that no residual is evaluated outside the range (e.g. C < 0).
void ParameterShooting::evaluate(const Eigen::VectorXd& q, double value, Eigen::VectorXd& residual,
                                 Eigen::MatrixXd* jacobian, Eigen::MatrixXd* propagator) const {
  const double omega_b = setup_.omega_b;
  if (!jacobian) {
    at(value).evaluate(q, omega_b, residual, nullptr, propagator);
    return;
  }
  const double h = 1e-6 * std::max(1.0, std::abs(value));
  const bool below = setup_.range.contains(value - h), above = setup_.range.contains(value + h);
  Eigen::VectorXd first, second;
  if (below == above) {  // inside the range (or a range narrower than 2h: central anyway)
    at(value + h).evaluate(q, omega_b, first, nullptr);
    at(value - h).evaluate(q, omega_b, second, nullptr);
    at(value).evaluate(q, omega_b, residual, jacobian, propagator);
    jacobian->col(jacobian->cols() - 1) = (first - second) / (2 * h);
    return;
  }
  const double step = above ? h : -h;
  at(value + step).evaluate(q, omega_b, first, nullptr);
  at(value + 2 * step).evaluate(q, omega_b, second, nullptr);
  at(value).evaluate(q, omega_b, residual, jacobian, propagator);
  jacobian->col(jacobian->cols() - 1) = (4 * first - second - 3 * residual) / (2 * step);
}

void ParameterShooting::jacobian_and_floquet(const Eigen::VectorXd& q, double value, Eigen::VectorXd& residual,
                                             Eigen::MatrixXd& jacobian, FloquetResult* floquet) const {
  evaluate(q, value, residual, &jacobian);
  if (floquet) {
    Eigen::VectorXd unused;
    Eigen::MatrixXd at_value;
    at(value).jacobian_and_floquet(q, setup_.omega_b, unused, at_value, floquet);
  }
}

void ParameterShooting::measure(const Eigen::VectorXd& z0, double value, DarkMeasures& out) const {
  at(value).measure(z0, setup_.omega_b, out);
}

std::optional<Index> ParameterShooting::contact_changes_per_period(const Eigen::VectorXd& z0, double value) const {
  return at(value).contact_changes_per_period(z0, setup_.omega_b);
}

}  // namespace lrchain::sim::dark
