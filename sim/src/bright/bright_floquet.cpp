// Floquet multipliers of a bright breather with the trivial +1 ones removed (bright_floquet.hpp).
#include "lrchain/sim/bright/bright_floquet.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>

#include <Eigen/Eigenvalues>
#include <Eigen/LU>

#include "lrchain/errors.hpp"

namespace lrchain::sim::bright {

BrightFloquet bright_floquet(const Eigen::MatrixXd& monodromy, bool mean_flow, const BrightFloquetOptions& o) {
  Eigen::EigenSolver<Eigen::MatrixXd> solver(monodromy, false);
  if (solver.info() != Eigen::Success) throw NumericalFailure("Floquet: eigenvalue solver failed");
  const auto& values = solver.eigenvalues();
  std::vector<std::complex<double>> lambda(values.data(), values.data() + values.size());
  BrightFloquet f;
  f.trivial_expected = mean_flow ? 4 : 2;
  f.det_defect = std::abs(monodromy.partialPivLu().determinant() - 1.0);
  dark::FloquetOptions classify;
  classify.unit_tolerance = o.unit_tolerance;
  classify.symmetry_tolerance = o.trivial_tolerance;
  classify.symmetry_multipliers = f.trivial_expected;
  std::vector<std::size_t> order(lambda.size());
  std::iota(order.begin(), order.end(), std::size_t(0));
  std::sort(order.begin(), order.end(),
            [&](std::size_t a, std::size_t b) { return std::abs(lambda[a] - 1.0) < std::abs(lambda[b] - 1.0); });
  const std::size_t count = std::min(order.size(), std::size_t(f.trivial_expected));
  std::vector<bool> trivial(lambda.size(), false);
  for (std::size_t k = 0; k < count; ++k) {
    trivial[order[k]] = true;
    f.trivial.push_back(lambda[order[k]]);
    f.trivial_distance = std::max(f.trivial_distance, std::abs(lambda[order[k]] - 1.0));
  }
  f.trivial_found = count == std::size_t(f.trivial_expected) && f.trivial_distance <= o.trivial_tolerance;
  for (std::size_t i = 0; i < lambda.size(); ++i) {
    if (trivial[i]) continue;
    const double m = std::abs(lambda[i]);
    f.max_nontrivial_modulus = std::max(f.max_nontrivial_modulus, m);
    f.unit_circle_defect = std::max(f.unit_circle_defect, std::abs(m - 1.0));
  }
  f.stable = f.trivial_found && f.max_nontrivial_modulus <= 1.0 + o.unit_tolerance;
  f.multipliers = dark::classify_multipliers(std::move(lambda), classify);
  return f;
}

}  // namespace lrchain::sim::bright
