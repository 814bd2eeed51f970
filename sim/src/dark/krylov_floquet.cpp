// Leading Floquet multipliers by Spectra's restarted Arnoldi on monodromy-vector products
// (krylov_floquet.hpp).
#include "lrchain/sim/dark/krylov_floquet.hpp"

#include <algorithm>
#include <numbers>
#include <string>

#include <Spectra/GenEigsSolver.h>

#include "lrchain/errors.hpp"
#include "lrchain/sim/dark/shooting.hpp"

namespace lrchain::sim::dark {

namespace {

// Spectra's operator protocol: y = M x, the tangent [x] replayed with the orbit over one period.
class MonodromyOperator {
 public:
  using Scalar = double;
  MonodromyOperator(const DarkOrbit& orbit, const DarkOrbit::RecordedSteps& steps, const Eigen::VectorXd& z0)
      : orbit_(orbit), steps_(steps), z0_(z0), size_(2 * orbit.positions()), extended_(std::size_t(2 * size_), 0.0) {}
  Eigen::Index rows() const { return size_; }
  Eigen::Index cols() const { return size_; }
  void perform_op(const double* x, double* y) const {
    const std::size_t n = std::size_t(size_), P = n / 2;
    std::fill(extended_.begin(), extended_.end(), 0.0);
    std::copy(z0_.data(), z0_.data() + P, extended_.begin());
    std::copy(x, x + n, extended_.begin() + std::ptrdiff_t(n));
    orbit_.replay(steps_, extended_, 1);
    std::copy(extended_.begin() + std::ptrdiff_t(n), extended_.end(), y);
    ++products;
  }
  mutable Index products = 0;

 private:
  const DarkOrbit& orbit_;
  const DarkOrbit::RecordedSteps& steps_;
  const Eigen::VectorXd& z0_;
  Eigen::Index size_;
  mutable std::vector<double> extended_;
};

}  // namespace

KrylovFloquetResult leading_multipliers(const DarkShooting& shooting, const Eigen::VectorXd& z0, double omega_b,
                                        const KrylovFloquetOptions& o) {
  const DarkOrbit& orbit = shooting.orbit();
  const Index n = 2 * orbit.positions();
  if (o.count < 1 || o.count > n - 2)
    throw InvalidParameter("floquet_count", "must be in [1, " + std::to_string(n - 2) + "], got " + std::to_string(o.count));
  const Index subspace = std::min(n, o.subspace > 0 ? std::max(o.subspace, o.count + 2) : std::max(2 * o.count + 1, o.count + 20));
  std::vector<double> state(std::size_t(n), 0.0);
  std::copy(z0.data(), z0.data() + orbit.positions(), state.begin());
  DarkOrbit::RecordedSteps steps;
  orbit.record(state, 0.0, 2.0 * std::numbers::pi / omega_b, steps);
  if (steps.size.empty()) throw NumericalFailure("Floquet: the orbit ran away over one period");
  MonodromyOperator op(orbit, steps, z0);
  Spectra::GenEigsSolver<MonodromyOperator> arnoldi(op, o.count, subspace);
  arnoldi.init();
  arnoldi.compute(Spectra::SortRule::LargestMagn, o.max_restarts, o.tolerance);
  KrylovFloquetResult r;
  r.requested = o.count;
  r.restarts = arnoldi.num_iterations();
  r.products = op.products;
  r.converged = arnoldi.info() == Spectra::CompInfo::Successful;
  const Eigen::VectorXcd values = arnoldi.eigenvalues();  // the converged ones
  r.multipliers.assign(values.data(), values.data() + values.size());
  std::stable_sort(r.multipliers.begin(), r.multipliers.end(),
                   [](auto a, auto b) { return std::abs(a) > std::abs(b); });
  return r;
}

}  // namespace lrchain::sim::dark
