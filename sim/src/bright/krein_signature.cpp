// Krein signatures of the multipliers on the unit circle (krein_signature.hpp).
#include "lrchain/sim/bright/krein_signature.hpp"

#include <algorithm>
#include <cmath>
#include <optional>

#include <Eigen/Eigenvalues>

#include "lrchain/errors.hpp"

namespace lrchain::sim::bright {

namespace {

// Im(v^H J v) / 2 = sum_i m_i Im(conj(u_i) udot_i) for v = [u, udot] (J = [[0, diag(m)], [-diag(m), 0]]).
double symplectic_form(const Eigen::VectorXcd& v, const Eigen::VectorXd& masses) {
  const Eigen::Index n = masses.size();
  double form = 0;
  for (Eigen::Index i = 0; i < n; ++i) form += masses[i] * std::imag(std::conj(v[i]) * v[n + i]);
  return form;
}

// The multipliers on the upper unit circle (as krein_signatures) with the signature `signature_of`
// gives their eigenvector, ordered by angle.
template <class Signature>
std::vector<KreinMultiplier> signatures_on_circle(const Eigen::MatrixXd& monodromy, double unit_tolerance,
                                                  double trivial_radius, Signature signature_of) {
  Eigen::EigenSolver<Eigen::MatrixXd> solver(monodromy, true);
  if (solver.info() != Eigen::Success) throw NumericalFailure("Krein signature: eigenvalue solver failed");
  std::vector<KreinMultiplier> found;
  for (Eigen::Index k = 0; k < solver.eigenvalues().size(); ++k) {
    const std::complex<double> l = solver.eigenvalues()[k];
    if (l.imag() <= 1e-9 || std::abs(std::abs(l) - 1.0) > unit_tolerance) continue;
    if (std::abs(l - 1.0) <= trivial_radius * (1 + 1e-6)) continue;
    found.push_back({l, signature_of(Eigen::VectorXcd(solver.eigenvectors().col(k)))});
  }
  std::sort(found.begin(), found.end(),
            [](const KreinMultiplier& a, const KreinMultiplier& b) { return std::arg(a.lambda) < std::arg(b.lambda); });
  return found;
}

}  // namespace

std::vector<KreinMultiplier> krein_signatures(const Eigen::MatrixXd& monodromy, const Eigen::VectorXd& masses,
                                              double unit_tolerance, double trivial_radius) {
  if (monodromy.rows() != 2 * masses.size() || monodromy.cols() != 2 * masses.size())
    throw InvalidParameter("masses", "one per position: half the size of the monodromy matrix");
  return signatures_on_circle(monodromy, unit_tolerance, trivial_radius, [&](const Eigen::VectorXcd& v) {
    return symplectic_form(v, masses) > 0 ? 1 : -1;
  });
}

// u_0[n] = sum_{j <= n} r[j], u_f = u_0 + w_f, less the centre of mass sum m u / sum m (positions and velocities alike).
Eigen::VectorXcd ring_displacements_of_strain(const Eigen::VectorXcd& v, const Eigen::VectorXd& masses, Index sites) {
  const Eigen::Index positions = masses.size();
  if (sites < 1 || positions % sites != 0)
    throw InvalidParameter("sites", "must divide the number of positions (fields x sites)");
  if (v.size() != 2 * positions) throw InvalidParameter("masses", "one per position: half the size of the state");
  const Index fields = positions / sites;
  Eigen::VectorXcd u(v.size());
  for (Eigen::Index half = 0; half < 2; ++half) {
    const Eigen::Index o = half * positions;
    std::complex<double> sum = 0;
    for (Index n = 0; n < sites; ++n) u[o + n] = sum += v[o + n];
    for (Index f = 1; f < fields; ++f)
      for (Index n = 0; n < sites; ++n) u[o + f * sites + n] = u[o + n] + v[o + f * sites + n];
    const std::complex<double> centre = masses.cast<std::complex<double>>().dot(u.segment(o, positions)) / masses.sum();
    u.segment(o, positions).array() -= centre;
  }
  return u;
}

std::vector<KreinMultiplier> strain_krein_signatures(const Eigen::MatrixXd& monodromy, const Eigen::VectorXd& masses,
                                                     Index sites, double unit_tolerance, double trivial_radius) {
  const Eigen::Index positions = masses.size();
  if (monodromy.rows() != 2 * positions || monodromy.cols() != 2 * positions)
    throw InvalidParameter("masses", "one per position: half the size of the monodromy matrix");
  return signatures_on_circle(monodromy, unit_tolerance, trivial_radius, [&](const Eigen::VectorXcd& v) {
    // ring closure: sum r = 0 and sum rdot = 0 (krein_signature.hpp), within 1e-6 of the L1 size of the
    // positions' and the velocities' halves of v
    const std::complex<double> strain = v.head(sites).sum(), rate = v.segment(positions, sites).sum();
    if (std::abs(strain) > 1e-6 * v.head(positions).cwiseAbs().sum() ||
        std::abs(rate) > 1e-6 * v.tail(positions).cwiseAbs().sum())
      return 0;
    return symplectic_form(ring_displacements_of_strain(v, masses, sites), masses) > 0 ? 1 : -1;
  });
}

}  // namespace lrchain::sim::bright
