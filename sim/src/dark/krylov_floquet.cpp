// Leading Floquet multipliers by Spectra's restarted Arnoldi on monodromy-vector products
// (krylov_floquet.hpp).
#include "lrchain/sim/dark/krylov_floquet.hpp"

#include <algorithm>
#include <string>

#include <Spectra/GenEigsSolver.h>

#include "lrchain/errors.hpp"
#include "lrchain/sim/dark/monodromy_product.hpp"

namespace lrchain::sim::dark {

namespace {

// Spectra's operator protocol on the shared monodromy-vector product.
class MonodromyOperator {
 public:
  using Scalar = double;
  explicit MonodromyOperator(const MonodromyProduct& product) : product_(product) {}
  Eigen::Index rows() const { return product_.size(); }
  Eigen::Index cols() const { return product_.size(); }
  void perform_op(const double* x, double* y) const { product_.apply(x, y); }

 private:
  const MonodromyProduct& product_;
};

}  // namespace

KrylovFloquetResult leading_multipliers(const DarkShooting& shooting, const Eigen::VectorXd& z0, double omega_b,
                                        const KrylovFloquetOptions& o) {
  const DarkOrbit& orbit = shooting.orbit();
  const Index n = 2 * orbit.positions();
  if (o.count < 1 || o.count > n - 2)
    throw InvalidParameter("floquet_count", "must be in [1, " + std::to_string(n - 2) + "], got " + std::to_string(o.count));
  const Index subspace = std::min(n, o.subspace > 0 ? std::max(o.subspace, o.count + 2) : std::max(2 * o.count + 1, o.count + 20));
  const MonodromyProduct product(shooting, z0, omega_b);
  MonodromyOperator op(product);
  Spectra::GenEigsSolver<MonodromyOperator> arnoldi(op, o.count, subspace);
  arnoldi.init();
  arnoldi.compute(Spectra::SortRule::LargestMagn, o.max_restarts, o.tolerance);
  KrylovFloquetResult r;
  r.requested = o.count;
  r.restarts = arnoldi.num_iterations();
  r.products = product.products();
  r.converged = arnoldi.info() == Spectra::CompInfo::Successful;
  const Eigen::VectorXcd values = arnoldi.eigenvalues();  // the converged ones
  r.multipliers.assign(values.data(), values.data() + values.size());
  std::stable_sort(r.multipliers.begin(), r.multipliers.end(),
                   [](auto a, auto b) { return std::abs(a) > std::abs(b); });
  return r;
}

}  // namespace lrchain::sim::dark
