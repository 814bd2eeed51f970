#include "lrchain/sim/dark/floquet.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include <Eigen/Eigenvalues>
#include <Eigen/LU>

#include "lrchain/errors.hpp"

namespace lrchain::sim::dark {

std::string FloquetResult::kind() const {
  std::string k;
  auto add = [&](const char* s) { k += k.empty() ? s : std::string("+") + s; };
  if (real_instability) add("real");
  if (period_doubling) add("period-doubling");
  if (oscillatory) add("oscillatory");
  return k.empty() ? "stable" : k;
}

FloquetResult classify_multipliers(std::vector<std::complex<double>> lambda,
                                   const FloquetOptions& o) {
  FloquetResult r;
  const std::size_t n = lambda.size();
  // Symmetry modes: the symmetry_multipliers closest to +1 (within tolerance).
  std::vector<std::size_t> order(n);
  for (std::size_t i = 0; i < n; ++i) order[i] = i;
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    return std::abs(lambda[a] - 1.0) < std::abs(lambda[b] - 1.0);
  });
  std::vector<bool> symmetry(n, false);
  for (std::size_t i = 0; i < n; ++i)
    if (std::abs(lambda[order[i]] - 1.0) <= o.symmetry_tolerance) {
      ++r.near_one;
      if (Index(i) < o.symmetry_multipliers) symmetry[order[i]] = true;
    }
  for (std::size_t i = 0; i < n; ++i) {
    const auto l = lambda[i];
    const double m = std::abs(l);
    r.max_modulus = std::max(r.max_modulus, m);
    r.log_det += std::log(m);
    if (symmetry[i] || m <= 1.0 + o.unit_tolerance) continue;
    const bool real = std::abs(l.imag()) <= o.real_tolerance * m;
    if (real && l.real() > 0) {
      r.real_instability = true;
      r.max_real = std::max(r.max_real, m);
    } else if (real) {
      r.period_doubling = true;
      r.max_period_doubling = std::max(r.max_period_doubling, m);
    } else {
      r.oscillatory = true;
      r.max_oscillatory = std::max(r.max_oscillatory, m);
    }
  }
  for (std::size_t i = 0; i < n; ++i) {
    const auto inv = 1.0 / std::conj(lambda[i]);
    double dp = INFINITY, dc = INFINITY;
    for (std::size_t j = 0; j < n; ++j) {
      dp = std::min(dp, std::abs(lambda[j] - inv));
      dc = std::min(dc, std::abs(lambda[j] - std::conj(lambda[i])));
    }
    r.pairing_defect = std::max(r.pairing_defect, dp / std::max(1.0, std::abs(inv)));
    r.conjugation_defect = std::max(r.conjugation_defect, dc);
  }
  std::sort(lambda.begin(), lambda.end(), [](auto a, auto b) { return std::abs(a) > std::abs(b); });
  r.multipliers = std::move(lambda);
  return r;
}

FloquetResult floquet_from_monodromy(const Eigen::MatrixXd& M, const FloquetOptions& o) {
  Eigen::EigenSolver<Eigen::MatrixXd> es(M, false);
  if (es.info() != Eigen::Success) throw NumericalFailure("Floquet: eigenvalue solver failed");
  std::vector<std::complex<double>> l(es.eigenvalues().data(),
                                      es.eigenvalues().data() + es.eigenvalues().size());
  return classify_multipliers(std::move(l), o);
}

FloquetResult floquet_reversible(const ResonantChainShooting& shooting, const Eigen::MatrixXd& A,
                                 const FloquetOptions& o) {
  if (shooting.mode() != ShootingMode::reversible)
    throw std::invalid_argument("floquet_reversible: needs the reversible shooting propagator");
  const Index N = shooting.sites();
  const Index n2 = 2 * N, n4 = 4 * N;
  if (A.rows() != n4 || A.cols() != n4) throw std::invalid_argument("floquet_reversible: 4N x 4N");
  // Involution applied to the right of X = A^{-1} W A: W = S (site) or R S (bond).
  Eigen::MatrixXd WA(n4, n2);  // only the first 2N columns of W A are needed for P
  const bool bond = shooting.center() == DarkCenter::bond;
  for (Eigen::Index row = 0; row < n4; ++row) {
    const Eigen::Index block = row / N;  // 0: x, 1: y, 2: xdot, 3: ydot
    const Index i = row % N;
    const Eigen::Index src = block * N + (bond ? shooting.reflect(i) : i);
    const double sign = block >= 2 ? -1.0 : 1.0;
    WA.row(row) = sign * A.block(src, 0, 1, n2);
  }
  const Eigen::MatrixXd X = A.partialPivLu().solve(WA);  // first 2N columns of A^{-1} W A
  const Eigen::MatrixXd P = X.topRows(n2);
  Eigen::EigenSolver<Eigen::MatrixXd> es(P, false);
  if (es.info() != Eigen::Success) throw NumericalFailure("Floquet: eigenvalue solver failed");
  std::vector<std::complex<double>> l;
  l.reserve(static_cast<std::size_t>(n4));
  for (Eigen::Index i = 0; i < es.eigenvalues().size(); ++i) {
    const std::complex<double> mu = es.eigenvalues()(i);
    const std::complex<double> root = std::sqrt(mu * mu - 1.0);
    std::complex<double> a = mu + root, b = mu - root;
    if (bond) {
      a *= a;
      b *= b;
    }
    l.push_back(a);
    l.push_back(b);
  }
  return classify_multipliers(std::move(l), o);
}

}  // namespace lrchain::sim::dark
