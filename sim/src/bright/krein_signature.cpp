// Krein signatures of the multipliers on the unit circle (krein_signature.hpp).
#include "lrchain/sim/bright/krein_signature.hpp"

#include <algorithm>
#include <cmath>

#include <Eigen/Eigenvalues>

#include "lrchain/errors.hpp"

namespace lrchain::sim::bright {

std::vector<KreinMultiplier> krein_signatures(const Eigen::MatrixXd& monodromy, const Eigen::VectorXd& masses,
                                              double unit_tolerance, double trivial_radius) {
  const Eigen::Index n = masses.size();
  if (monodromy.rows() != 2 * n || monodromy.cols() != 2 * n)
    throw InvalidParameter("masses", "one per position: half the size of the monodromy matrix");
  Eigen::EigenSolver<Eigen::MatrixXd> solver(monodromy, true);
  if (solver.info() != Eigen::Success) throw NumericalFailure("Krein signature: eigenvalue solver failed");
  std::vector<KreinMultiplier> found;
  for (Eigen::Index k = 0; k < solver.eigenvalues().size(); ++k) {
    const std::complex<double> l = solver.eigenvalues()[k];
    if (l.imag() <= 1e-9 || std::abs(std::abs(l) - 1.0) > unit_tolerance) continue;
    if (std::abs(l - 1.0) <= trivial_radius * (1 + 1e-6)) continue;
    const Eigen::VectorXcd v = solver.eigenvectors().col(k);
    // v^H J v = sum_i m_i (conj(q_i) qdot_i - conj(qdot_i) q_i) = 2 i sum_i m_i Im(conj(q_i) qdot_i)
    double form = 0;
    for (Eigen::Index i = 0; i < n; ++i) form += masses[i] * std::imag(std::conj(v[i]) * v[n + i]);
    found.push_back({l, form > 0 ? 1 : -1});
  }
  std::sort(found.begin(), found.end(),
            [](const KreinMultiplier& a, const KreinMultiplier& b) { return std::arg(a.lambda) < std::arg(b.lambda); });
  return found;
}

}  // namespace lrchain::sim::bright
