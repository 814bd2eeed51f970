// Perturbations of a dark breather's start (perturbation.hpp).
#include "lrchain/sim/dark/perturbation.hpp"

#include <Eigen/Eigenvalues>
#include <random>

namespace lrchain::sim::dark {

DarkPerturbation unstable_perturbation(const Eigen::MatrixXd& monodromy, double size) {
  Eigen::EigenSolver<Eigen::MatrixXd> solver(monodromy);
  Eigen::Index best = 0;
  for (Eigen::Index i = 1; i < solver.eigenvalues().size(); ++i)
    if (std::abs(solver.eigenvalues()(i)) > std::abs(solver.eigenvalues()(best))) best = i;
  DarkPerturbation out;
  out.multiplier = solver.eigenvalues()(best);
  const Eigen::VectorXcd v = solver.eigenvectors().col(best);
  Eigen::VectorXd direction = v.real();
  if (direction.cwiseAbs().maxCoeff() < 1e-3 * v.cwiseAbs().maxCoeff()) direction = v.imag();
  Eigen::Index largest = 0;
  direction.cwiseAbs().maxCoeff(&largest);
  out.vector = direction * (size / std::abs(direction(largest))) * (direction(largest) < 0 ? -1.0 : 1.0);
  return out;
}

DarkPerturbation random_perturbation(Index positions, double size, std::uint64_t seed) {
  std::mt19937_64 random(seed);
  DarkPerturbation out;
  out.vector = Eigen::VectorXd::Zero(2 * positions);
  // uniform_real_distribution's algorithm is left to the library; mt19937_64 is fully specified.
  for (Index i = 0; i < positions; ++i)
    out.vector(i) = size * (2.0 * (double(random() >> 11) * 0x1.0p-53) - 1.0);
  return out;
}

}  // namespace lrchain::sim::dark
