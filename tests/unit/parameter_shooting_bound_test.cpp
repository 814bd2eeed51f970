// dF/dp of the parameter shooting (sim/dark/parameter_shooting.hpp) at a bound of the parameter's range:
// one-sided there (no orbit integrated outside the range), central inside, both equal to fourth-order
// one-sided differences of the residual computed in this test. (klein_gordon is smooth in C across
// C = 0, so a central difference there would agree too: this checks the one-sided formula.)
#include <doctest/doctest.h>

#include <cmath>

#include "lrchain/model.hpp"
#include "lrchain/sim/dark/parameter_shooting.hpp"
#include "lrchain/sim/model_lattice.hpp"
#include "lrchain/sim/model_lattice_bloch.hpp"

using namespace lrchain;

namespace {

// The last Jacobian column of klein_gordon's shooting continued in C at `value`, with C's range `range`.
Eigen::VectorXd parameter_column(const Model& model, const ModelParameter& range, double value, const Eigen::VectorXd& q,
                                 Eigen::VectorXd* residual_at = nullptr) {
  sim::dark::ParameterShootingSetup setup;
  setup.kernels = sim::shipped_lattice_kernels("klein_gordon");
  setup.parameters = sim::lattice_parameters(model);
  setup.index = 0;  // C, the first parameter of models/klein_gordon.toml
  setup.range = range;
  setup.sites = 21;
  setup.omega_b = 1.19;
  const sim::dark::ParameterShooting shooting(setup);
  Eigen::VectorXd residual;
  Eigen::MatrixXd jacobian;
  shooting.evaluate(q, value, residual, &jacobian);
  if (residual_at) *residual_at = residual;
  return jacobian.col(jacobian.cols() - 1);
}

// dF/dC at `value` from residuals at value + k d, k = 0..4, on one side (d > 0 or < 0): fourth-order
// one-sided differences (Fornberg's weights -25/12, 4, -3, 4/3, -1/4).
Eigen::VectorXd reference_column(const Model& model, const ModelParameter& range, double value, double d,
                                 const Eigen::VectorXd& q) {
  const double w[] = {-25.0 / 12, 4, -3, 4.0 / 3, -0.25};
  Eigen::VectorXd sum;
  for (int k = 0; k <= 4; ++k) {
    sim::dark::ParameterShootingSetup setup;
    setup.kernels = sim::shipped_lattice_kernels("klein_gordon");
    setup.parameters = sim::lattice_parameters(model);
    setup.index = 0;
    setup.range = range;
    setup.sites = 21;
    setup.omega_b = 1.19;
    const sim::dark::ParameterShooting shooting(setup);
    Eigen::VectorXd r;
    shooting.evaluate(q, value + k * d, r, nullptr);
    sum = k == 0 ? Eigen::VectorXd(w[k] * r) : Eigen::VectorXd(sum + w[k] * r);
  }
  return sum / d;
}

}  // namespace

TEST_CASE("parameter shooting: dF/dC at the bounds of C's range is one-sided and right" * doctest::test_suite("fast")) {
  const Model model = shipped_model("klein_gordon", {});
  REQUIRE(model.definition().parameters.at(0).name == "C");
  const ModelParameter range = model.definition().parameters.at(0);  // [0, inf)
  // A state with every site moving (the shooting's unknowns), not a breather: dF/dC is smooth anyway.
  sim::dark::ParameterShootingSetup probe;
  probe.kernels = sim::shipped_lattice_kernels("klein_gordon");
  probe.parameters = sim::lattice_parameters(model);
  probe.range = range;
  probe.sites = 21;
  probe.omega_b = 1.19;
  const Eigen::Index n = sim::dark::ParameterShooting(probe).unknowns();
  Eigen::VectorXd q(n);
  for (Eigen::Index i = 0; i < n; ++i) q[i] = 0.2 * std::cos(0.7 * double(i)) * std::exp(-0.02 * double(i));

  // The anti-continuum limit C = 0 of [0, inf): forward differences only.
  const Eigen::VectorXd at_zero = parameter_column(model, range, 0.0, q);
  const Eigen::VectorXd forward = reference_column(model, range, 0.0, 1e-3, q);
  REQUIRE(at_zero.allFinite());
  CHECK((at_zero - forward).norm() <= 1e-6 * forward.norm());
  // An upper bound (C in (-inf, 0.1]): backward differences at C = 0.1.
  ModelParameter upper = range;
  upper.has_lower = false;
  upper.has_upper = true;
  upper.upper_closed = true;
  upper.upper = 0.1;
  const Eigen::VectorXd at_top = parameter_column(model, upper, 0.1, q);
  const Eigen::VectorXd backward = reference_column(model, upper, 0.1, -1e-3, q);
  CHECK((at_top - backward).norm() <= 1e-6 * backward.norm());
  // Inside the range the central difference gives the same derivative as the one-sided reference.
  const Eigen::VectorXd inside = parameter_column(model, range, 0.1, q);
  CHECK((inside - backward).norm() <= 1e-6 * backward.norm());
}
